#include "test_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "engine/io/argoverse_log.h"
#include "engine/io/tum_trajectory.h"
#include "engine/sim/log_writer.h"

namespace hdprior::test {
namespace fs = std::filesystem;

fs::path sharedDataDir() {
  const char* env = std::getenv("HDPRIOR_SHARED_DATA");
  return fs::path(env ? env : HDPRIOR_SHARED_DATA);
}

fs::path sourceDir() { return fs::path(HDPRIOR_SOURCE_DIR); }

fs::path sharedLog() {
  const fs::path log = sharedDataDir() / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede";
  if (!fs::is_directory(log / "sensors" / "lidar")) {
    ADD_FAILURE() << "the shared Argoverse 2 test log is missing: expected it at " << log
                  << " (the folder ../shared/data beside the repository, or set HDPRIOR_SHARED_DATA)";
    throw std::runtime_error("shared data missing");
  }
  return log;
}

std::string quoted(const fs::path& p) {
  std::string s = "'";  // appended, not "'" + string: GCC 12 warns falsely (-Wrestrict) on that
  s += p.string();
  s += "'";
  return s;
}

fs::path freshOutputDir(const std::string& name) {
  const fs::path dir = fs::path(HDPRIOR_TEST_OUTPUT) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

namespace {

// ctest runs every test in its own process, so folders named after the process pile up: one run
// of the suite left 6.5 GB of copied logs behind. They go when the process's tests pass; a failed
// test's folder stays to be looked at.
class ProcessOutputCleanup : public ::testing::Environment {
 public:
  void add(const fs::path& dir) { dirs_.push_back(dir); }
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Passed()) return;
    for (const fs::path& dir : dirs_) {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  }

 private:
  std::vector<fs::path> dirs_;
};

// Registered before main runs: gtest only calls environments added before RUN_ALL_TESTS.
ProcessOutputCleanup* const processOutputCleanup =
    static_cast<ProcessOutputCleanup*>(::testing::AddGlobalTestEnvironment(new ProcessOutputCleanup));

}  // namespace

fs::path processOutputDir(const std::string& name) {
  const fs::path dir = freshOutputDir(name + "_" + std::to_string(::getpid()));
  processOutputCleanup->add(dir);
  return dir;
}

std::string readFileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CommandResult runHdprior(const std::string& args) {
  const fs::path dir = fs::path(HDPRIOR_TEST_OUTPUT) / "cmd";
  fs::create_directories(dir);
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(std::rand());
  const fs::path out = dir / ("out" + tag), err = dir / ("err" + tag);
  const std::string cmd = std::string("'") + HDPRIOR_BINARY + "' " + args + " >'" + out.string() + "' 2>'" +
                          err.string() + "'";
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = readFileText(out);
  r.err = readFileText(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

namespace {

// The engine library's build time: shared drives simulated by an older engine are never reused.
std::string engineBuildStamp() {
  std::error_code ec;
  const auto time = fs::last_write_time(HDPRIOR_ENGINE_LIBRARY, ec);
  return ec ? std::string("unknown") : std::to_string(time.time_since_epoch().count());
}

// An exclusive lock on a file, held while the object lives (flock: released if the process dies).
class FileLock {
 public:
  explicit FileLock(const fs::path& file) : fd_(::open(file.c_str(), O_CREAT | O_RDWR, 0644)) {
    if (fd_ < 0 || ::flock(fd_, LOCK_EX) != 0) throw std::runtime_error("cannot lock " + file.string());
  }
  ~FileLock() {
    ::flock(fd_, LOCK_UN);
    ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

fs::path sharedTownDrive(int town, int seed, double seconds) {
  char key[96];
  std::snprintf(key, sizeof key, "town%d_seed%d_%gs", town, seed, seconds);
  const fs::path root = fs::path(HDPRIOR_TEST_OUTPUT) / "shared_drives" / engineBuildStamp();
  fs::create_directories(root);
  const fs::path folder = root / key, done = root / (std::string(key) + ".log");
  FileLock lock(root / (std::string(key) + ".lock"));
  if (!fs::exists(done)) {  // the first process to get here simulates it; the others wait on the lock
    fs::remove_all(folder);
    SimulationOptions sim;
    sim.townSeed = uint64_t(town);
    sim.seed = uint64_t(seed);
    sim.seconds = seconds;
    sim.outDir = folder;
    const std::string id = simulateLog(sim).logId;
    std::ofstream(root / (std::string(key) + ".log.partial")) << id;
    fs::rename(root / (std::string(key) + ".log.partial"), done);
  }
  return folder / readFileText(done);
}

fs::path copySharedTownDrive(int town, int seed, double seconds, const fs::path& outDir) {
  const fs::path shared = sharedTownDrive(town, seed, seconds);
  const fs::path log = outDir / shared.filename();
  fs::create_directories(outDir);
  fs::copy(shared, log, fs::copy_options::recursive);
  return log;
}

SimulatedDrive simulatedTownDrive(const std::string& name, int town, int seed, double seconds) {
  const fs::path dir = processOutputDir(name);
  return {dir, copySharedTownDrive(town, seed, seconds, dir)};
}

std::filesystem::path writeMovedTruth(const std::filesystem::path& log, const std::filesystem::path& file, double dx, double dy,
                                      double dz) {
  const PoseTrajectory truth = ArgoverseLog(log).cityTEgoAtSweeps();
  std::vector<SE3> moved = truth.poses();
  for (SE3& pose : moved) pose.translation() += Eigen::Vector3d(dx, dy, dz);
  writeTum(file, PoseTrajectory(truth.timestamps(), moved));
  return file;
}

::testing::AssertionResult failedWithOneLine(const CommandResult& r, const std::string& message) {
  if (r.status != 2) return ::testing::AssertionFailure() << "exit status " << r.status << ", not 2; stderr: " << r.err;
  if (r.err.find(message) == std::string::npos) return ::testing::AssertionFailure() << "'" << message << "' not in: " << r.err;
  if (std::count(r.err.begin(), r.err.end(), '\n') != 1) return ::testing::AssertionFailure() << "not one line: " << r.err;
  return ::testing::AssertionSuccess();
}

}  // namespace hdprior::test
