#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_data.h"

namespace hdprior::test {
namespace {

const char* const kCommands[] = {"info", "export-map", "run",      "eval", "merge",  "degrade-trajectory",
                                 "demo", "sim",        "match",    "snapshot", "view", "config", "plot", "changes"};

// Every command answers --help with its usage and each option's default, and exits 0.
TEST(CommandHelp, EveryCommandPrintsItsUsage) {
  for (const std::string command : kCommands) {
    const CommandResult r = runHdprior(command + " --help");
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_TRUE(r.err.empty()) << command << ": " << r.err;
    EXPECT_NE(r.out.find("Usage: hdprior " + command + " [OPTIONS]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("-h,--help"), std::string::npos) << r.out;
  }
}

TEST(CommandHelp, ShowsDefaultsAndRequiredOptions) {
  const CommandResult sim = runHdprior("sim --help");
  EXPECT_NE(sim.out.find("--noise M=0.02"), std::string::npos) << sim.out;
  EXPECT_NE(sim.out.find("--threads T=2"), std::string::npos) << sim.out;
  EXPECT_NE(sim.out.find("--out DIR REQUIRED"), std::string::npos) << sim.out;
  const CommandResult snapshot = runHdprior("snapshot --help");
  EXPECT_NE(snapshot.out.find("--size WxH=1280x720"), std::string::npos) << snapshot.out;
  EXPECT_NE(snapshot.out.find("--view top|orbit|landscape|inspector=top"), std::string::npos) << snapshot.out;
  const CommandResult run = runHdprior("run --help");
  EXPECT_NE(run.out.find("--odometry-frame first|city=first"), std::string::npos) << run.out;
}

// `hdprior --help` (and -h) lists every command; with no command at all the same text goes to
// stderr with exit status 2.
TEST(CommandHelp, TopLevelListsEveryCommand) {
  for (const char* help : {"--help", "-h"}) {
    const CommandResult r = runHdprior(help);
    EXPECT_EQ(r.status, 0) << r.err;
    for (const std::string command : kCommands) EXPECT_NE(r.out.find("\n  " + command + " "), std::string::npos) << command;
  }
  const CommandResult none = runHdprior("");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("Usage: hdprior"), std::string::npos) << none.err;
}

TEST(CommandVersion, PrintsTheProjectVersion) {
  const CommandResult r = runHdprior("--version");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "hdprior " HDPRIOR_VERSION "\n");
}

// A bad command line is one line on stderr naming the option or argument and the problem, exit 2.
TEST(CommandLineOptions, BadOptionsAreOneLineNamingTheOption) {
  const std::string log = "'" + sharedLog().string() + "'";
  const struct {
    std::string args, line;
  } cases[] = {
      {"--bogus", "hdprior: option --bogus: unknown option (try hdprior --help)"},
      {"nosuchcommand", "hdprior: unknown command 'nosuchcommand' (try hdprior --help)"},
      {"info " + log + " --bogus=3", "hdprior info: option --bogus: unknown option (try hdprior info --help)"},
      {"info", "hdprior info: argument LOG: is required (try hdprior info --help)"},
      {"export-map " + log, "hdprior export-map: option --out: is required (try hdprior export-map --help)"},
      {"export-map " + log + " --out /tmp/x --resolution ten", "hdprior export-map: option --resolution: 'ten' is not a number"},
      {"match " + log + " --frame 1.5", "hdprior match: option --frame: '1.5' is not an integer"},
      {"match " + log + " --frame", "hdprior match: option --frame: needs a value"},
      {"match " + log + " --frame 0 --backend gicp", "hdprior match: option --backend: 'gicp' is not ndt2d or pcl"},
      {"sim --town -1 --out /tmp/x", "hdprior sim: option --town: must not be negative"},
      {"eval /tmp --out /tmp/x --odometry-format tum", "hdprior eval: option --odometry-format: needs --odometry-dir"},
      {"snapshot " + log + " --frame 0 --out /tmp/x.png --view side", "hdprior snapshot: option --view: "},
  };
  for (const auto& c : cases) {
    const CommandResult r = runHdprior(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_EQ(r.err.rfind(c.line, 0), 0u) << c.args << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// The options' spellings stay as they were: -j2, --out=DIR, and the last of a repeated option wins.
TEST(CommandLineOptions, ShortInlineAndRepeatedForms) {
  const std::string out = freshOutputDir("command_line_forms").string();
  const CommandResult jobs = runHdprior("eval /nonexistent/logs --out=" + out + " -j0");
  EXPECT_NE(jobs.err.find("option --jobs: must be at least 1"), std::string::npos) << jobs.err;
  const CommandResult last =
      runHdprior("eval /nonexistent/logs --out " + out + " -j2 --odometry-dir /nonexistent/a --odometry-dir=/nonexistent/b");
  EXPECT_NE(last.err.find("option --odometry-dir: '/nonexistent/b' is not a folder"), std::string::npos) << last.err;
}

}  // namespace
}  // namespace hdprior::test
