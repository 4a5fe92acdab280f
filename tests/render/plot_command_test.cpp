#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include "bad_input.h"
#include "render/image_compare.h"
#include "synthetic_diagnostics.h"
#include "test_data.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

// A run folder holding only a keyframes.json of made-up diagnostics.
fs::path syntheticRun(const fs::path& dir, size_t keyframes, double phase) {
  fs::create_directories(dir);
  std::ofstream(dir / "keyframes.json") << keyframesJson(syntheticDiagnostics(keyframes, phase));
  return dir;
}

TEST(PlotCommand, DrawsTheGoldenOfARun) {
  const fs::path dir = freshOutputDir("plot_command");
  const fs::path run = syntheticRun(dir / "run_a", 40, 0.0), out = dir / "plot.png";
  const CommandResult r = runHdprior("plot " + quoted(run) + " --plots score,sigma_along,chi2,error_lateral --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("4 plots"), std::string::npos) << r.out;
  EXPECT_EQ(checkGolden(readPng(out), "plot_run"), "");
}

TEST(PlotCommand, DrawsTheGoldenOfTwoRunsCompared) {
  const fs::path dir = freshOutputDir("plot_command_compare");
  const fs::path a = syntheticRun(dir / "run_a", 40, 0.0), b = syntheticRun(dir / "run_b", 40, 1.0), out = dir / "plot.png";
  const CommandResult r =
      runHdprior("plot " + quoted(a) + " --compare " + quoted(b) + " --plots chi2,error_along --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(checkGolden(readPng(out), "plot_compare"), "");
}

// By default every plot with a value; a trailing slash on the folder is fine.
TEST(PlotCommand, DefaultIsEveryPlotWithAValue) {
  const fs::path dir = freshOutputDir("plot_command_default");
  const fs::path run = syntheticRun(dir / "run", 600, 0.0), out = dir / "all.png";
  const CommandResult r = runHdprior("plot " + quoted(fs::path(run.string() + "/")) + " --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("14 plots"), std::string::npos) << r.out;
  EXPECT_GT(readPng(out).height, 14 * 150);
}

// The folder `hdprior run` writes, from a simulated drive.
TEST(PlotCommand, PlotsTheRunFolderOfARealRun) {
  const SimulatedDrive drive = simulatedTownDrive("plot_command_real_run", 1, 1, 3.0);
  const CommandResult run = runHdprior("run " + quoted(drive.log) + " --out " + quoted(drive.folder / "run"));
  ASSERT_EQ(run.status, 0) << run.err;
  const fs::path out = drive.folder / "plot.png";
  const CommandResult r = runHdprior("plot " + quoted(drive.folder / "run") + " --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("plots"), std::string::npos) << r.out;
  EXPECT_GT(readPng(out).height, 300);
}

std::string substituted(std::string s, const std::string& key, const std::string& value) {
  for (size_t at = s.find(key); at != std::string::npos; at = s.find(key, at + value.size())) s.replace(at, key.size(), value);
  return s;
}

// BadInput::args: {A} is a good run folder, {D} the test's folder; --out is added.
class PlotCommandBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(PlotCommandBadInput, FailsWithOneLineAndNoFile) {
  const fs::path dir = freshOutputDir(std::string("plot_bad_") + GetParam().name);
  const fs::path good = syntheticRun(dir / "good", 10, 0.0), outDir = dir / "out";
  fs::create_directories(dir / "empty");
  fs::create_directories(dir / "corrupt");
  std::ofstream(dir / "corrupt" / "keyframes.json") << "[{\"index\": 0, \"frame\": ";
  fs::create_directories(dir / "not_a_list");
  std::ofstream(dir / "not_a_list" / "keyframes.json") << "{\"index\": 0}";
  fs::create_directories(dir / "no_diagnostics");
  std::ofstream(dir / "no_diagnostics" / "keyframes.json") << "[{\"index\": 0, \"frame\": 0, \"match\": {}}]";
  fs::create_directories(outDir);
  const std::string args = substituted(substituted(GetParam().args, "{A}", quoted(good)), "{D}", dir.string());
  const CommandResult r = runHdprior("plot " + args + " --out " + quoted(outDir / "plot.png"));
  EXPECT_TRUE(failedWithOneLine(r, GetParam().message));
  EXPECT_EQ(r.err.rfind("hdprior plot: ", 0), 0u) << r.err;
  EXPECT_TRUE(fs::is_empty(outDir)) << "files left behind in " << outDir;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PlotCommandBadInput,
    ::testing::Values(BadInput{"missing_run_dir", "{D}/no_such_run", "no_such_run: no such run folder"},
                      BadInput{"run_dir_is_a_file", "{D}/good/keyframes.json", "not a folder"},
                      BadInput{"missing_keyframes_json", "{D}/empty", "empty/keyframes.json: file not found"},
                      BadInput{"corrupt_keyframes_json", "{D}/corrupt", "corrupt/keyframes.json: not JSON"},
                      BadInput{"keyframes_json_not_a_list", "{D}/not_a_list", "not_a_list/keyframes.json: not a list"},
                      BadInput{"keyframe_without_diagnostics", "{D}/no_diagnostics", "no_diagnostics/keyframes.json: keyframe 0"},
                      BadInput{"unknown_plot", "{A} --plots score,clouds", "option --plots: unknown plot 'clouds'"},
                      BadInput{"empty_plot_name", "{A} --plots score,", "option --plots: empty plot name"},
                      BadInput{"missing_compare_dir", "{A} --compare {D}/no_such_b", "option --compare: "},
                      BadInput{"corrupt_compare", "{A} --compare {D}/corrupt", "corrupt/keyframes.json: not JSON"},
                      BadInput{"empty_compare", "{A} --compare ''", "option --compare: needs a run folder"},
                      BadInput{"missing_run_argument", "--plots score", "argument RUN_DIR: is required"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(PlotCommand, OutputFolderMissingOrADirectoryFails) {
  const fs::path dir = freshOutputDir("plot_bad_out");
  const fs::path run = syntheticRun(dir / "run", 10, 0.0);
  EXPECT_TRUE(failedWithOneLine(runHdprior("plot " + quoted(run) + " --out " + quoted(dir / "nope" / "x.png")),
                                "nope/x.png: its folder does not exist"));
  EXPECT_TRUE(failedWithOneLine(runHdprior("plot " + quoted(run) + " --out " + quoted(dir)), "is a directory"));
  EXPECT_TRUE(failedWithOneLine(runHdprior("plot " + quoted(run)), "option --out: is required"));
  EXPECT_FALSE(fs::exists(dir / "nope"));
}

}  // namespace
}  // namespace hdprior::test
