#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace hdprior::test {

// The real Argoverse 2 log in ../shared/data. Fails the calling test (never skips) with a
// message saying where the data is expected when it is not there.
std::filesystem::path sharedLog();
std::filesystem::path sharedDataDir();
// The repository (the source tree this build was configured from).
std::filesystem::path sourceDir();

// A fresh, empty directory for one test's outputs, under the build tree.
std::filesystem::path freshOutputDir(const std::string& name);
// A fresh directory named after `name` and this process (ctest runs the tests of one binary in
// parallel processes), removed when the process ends with every test passed.
std::filesystem::path processOutputDir(const std::string& name);
// A short simulated town drive (`hdprior sim --town town --seed seed --seconds seconds`) in
// processOutputDir(name); returns the folder it was written to and the log's folder in it.
struct SimulatedDrive {
  std::filesystem::path folder, log;
};
// The log is a copy of the shared drive below, so the test may change it.
SimulatedDrive simulatedTownDrive(const std::string& name, int town, int seed, double seconds);
// The log of that drive (simulateLog with townSeed = town, seed, seconds, everything else default),
// simulated once per ctest run and shared by every test process that asks for it: the first process
// simulates it into the build tree (output/shared_drives, cleared by the ctest fixture
// SharedDrives.Clear before a run and keyed by the engine library's build) while the others wait for
// it. Read only: copy it (copySharedTownDrive) before changing anything in it.
std::filesystem::path sharedTownDrive(int town, int seed, double seconds);
// A copy of sharedTownDrive(town, seed, seconds) at outDir/<log id>, as simulateLog would write it;
// returns outDir/<log id>.
std::filesystem::path copySharedTownDrive(int town, int seed, double seconds, const std::filesystem::path& outDir);
// A whole file as bytes in a string (empty if it cannot be read).
std::string readFileText(const std::filesystem::path& path);

// A log's ground truth at its sweeps moved by (dx, dy, dz) in the city frame, written to `file` as
// TUM: another system's trajectory of the log (read with --odometry-frame city it is off by the move).
std::filesystem::path writeMovedTruth(const std::filesystem::path& log, const std::filesystem::path& file, double dx, double dy,
                                      double dz);

// A path in single quotes, for runHdprior's command line.
std::string quoted(const std::filesystem::path& path);

// Runs the hdprior binary with arguments; returns exit status, captures stdout/stderr.
struct CommandResult {
  int status = -1;
  std::string out;
  std::string err;
};
CommandResult runHdprior(const std::string& args);

// Whether a command failed as bad input must: exit status 2 and one line on stderr holding `message`.
::testing::AssertionResult failedWithOneLine(const CommandResult& result, const std::string& message);

}  // namespace hdprior::test
