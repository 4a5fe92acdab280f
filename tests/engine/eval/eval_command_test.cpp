#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <tuple>
#include <sstream>

#include <unistd.h>

#include "engine/sim/log_writer.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(text);
  while (std::getline(in, field, separator)) out.push_back(field);
  return out;
}

// per_log.csv as rows of fields (no field of these logs is quoted but the error, which is last).
std::vector<std::vector<std::string>> perLogRows(const fs::path& out) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : split(test::readFileText(out / "per_log.csv"), '\n')) rows.push_back(split(line, ','));
  return rows;
}

size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  return size_t(it - header.begin());
}

std::string field(const std::vector<std::string>& row, size_t i) { return i < row.size() ? row[i] : ""; }

// per_log.csv without its time column, for comparing runs.
std::string perLogWithoutTimes(const fs::path& out) {
  auto rows = perLogRows(out);
  const size_t seconds = column(rows.at(0), "pipeline_s");
  std::string text;
  for (auto& row : rows) {
    if (seconds < row.size()) row[seconds].clear();
    for (const std::string& f : row) text += f + ",";
    text += "\n";
  }
  return text;
}

// The "hdprior <command>: log <id>: ..." lines of stderr, by log id.
std::map<std::string, std::string> logLines(const std::string& err, const std::string& command) {
  std::map<std::string, std::string> lines;
  const std::string prefix = "hdprior " + command + ": log ";
  for (const std::string& line : split(err, '\n')) {
    if (line.rfind(prefix, 0) != 0) continue;
    const std::string rest = line.substr(prefix.size());
    lines[rest.substr(0, rest.find(':'))] = rest;
  }
  return lines;
}

// Nothing temporary is left in an output folder: no ".tmp" file, no ".partial" folder.
void expectNothingTemporary(const fs::path& out) {
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
    EXPECT_EQ(name.find(".partial"), std::string::npos) << name;
  }
}

}  // namespace

// `hdprior eval` over two short simulated town drives and one log folder whose poses are truncated.
class EvalCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::processOutputDir("eval_logs"));
    fs::path first;
    for (int town : {1, 2}) {
      // simulateLog of town `town`, seed 1, 6 s, simulated once per ctest run and copied here.
      const fs::path log = test::copySharedTownDrive(town, 1, 6.0, *dir_ / ("town" + std::to_string(town)));
      if (first.empty()) first = log;
    }
    const fs::path broken = *dir_ / "broken";
    fs::create_directories(broken / "sensors" / "lidar");
    const std::string poses = test::readFileText(first / "city_SE3_egovehicle.feather");
    std::ofstream(broken / "city_SE3_egovehicle.feather", std::ios::binary) << poses.substr(0, poses.size() / 3);
  }
  static void TearDownTestSuite() { delete dir_; }
  static fs::path* dir_;
};
fs::path* EvalCommand::dir_ = nullptr;

TEST_F(EvalCommand, RunsEveryLogReportsTheBrokenOneAndIsTheSameForOneAndTwoWorkers) {
  const fs::path out2 = dir_->parent_path() / (dir_->filename().string() + "_out2");
  const auto r = test::runHdprior("eval " + dir_->string() + " --out " + out2.string() + " -j 2");
  EXPECT_EQ(r.status, 2) << r.err;
  // One error line, naming the broken log and its file; one progress line per log.
  const auto errLines = split(r.err, '\n');
  size_t errors = 0, progress = 0;
  for (const std::string& line : errLines) {
    if (line.rfind("hdprior eval: ", 0) == 0) {
      ++errors;
      EXPECT_NE(line.find("log broken: "), std::string::npos) << line;
      EXPECT_NE(line.find("broken/city_SE3_egovehicle.feather: "), std::string::npos) << line;
    }
    if (line.rfind("[", 0) == 0 && line.find("/3] ") != std::string::npos) ++progress;
  }
  EXPECT_EQ(errors, 1u) << r.err;
  EXPECT_EQ(progress, 3u) << r.err;

  const auto rows = perLogRows(out2);
  ASSERT_EQ(rows.size(), 4u);
  const auto& header = rows[0];
  const size_t error = column(header, "error"), odoMean = column(header, "odometry_ate_mean_m"),
               optRmse = column(header, "optimized_ate_rmse_m"), seconds = column(header, "pipeline_s");
  std::vector<std::vector<std::string>> good;
  for (size_t i = 1; i < rows.size(); ++i) {
    if (field(rows[i], error).empty()) {
      good.push_back(rows[i]);
      EXPECT_FALSE(field(rows[i], optRmse).empty());
      EXPECT_TRUE(fs::exists(out2 / rows[i][0] / "metrics.json")) << rows[i][0];
      EXPECT_TRUE(fs::exists(out2 / rows[i][0] / "optimized.tum")) << rows[i][0];
    } else {
      EXPECT_EQ(rows[i][0], "broken");
      EXPECT_NE(field(rows[i], error).find("city_SE3_egovehicle.feather"), std::string::npos);
    }
  }
  ASSERT_EQ(good.size(), 2u);

  // The table averages the two good logs.
  const auto table = split(test::readFileText(out2 / "table.csv"), '\n');
  ASSERT_EQ(table.size(), 3u);
  const auto odometry = split(table[1], ',');
  EXPECT_EQ(odometry[0], "odometry");
  EXPECT_EQ(odometry[1], "2");
  EXPECT_EQ(odometry[2], "1");
  EXPECT_NEAR(std::stod(odometry[3]), (std::stod(good[0][odoMean]) + std::stod(good[1][odoMean])) / 2, 2e-6);
  const auto optimized = split(table[2], ',');
  EXPECT_NEAR(std::stod(optimized[5]), (std::stod(good[0][optRmse]) + std::stod(good[1][optRmse])) / 2, 2e-6);
  EXPECT_NE(test::readFileText(out2 / "table.md").find("average over the 2 logs that went through (of 3; 1 failed)"), std::string::npos);
  const std::string png = test::readFileText(out2 / "rmse_boxplot.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  for (const auto& entry : fs::directory_iterator(out2)) EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos);

  // One worker: the same rows but for the timing column.
  const fs::path out1 = dir_->parent_path() / (dir_->filename().string() + "_out1");
  const auto r1 = test::runHdprior("eval " + dir_->string() + " --out " + out1.string() + " -j1");
  EXPECT_EQ(r1.status, 2) << r1.err;
  auto rows1 = perLogRows(out1), rows2 = rows;
  ASSERT_EQ(rows1.size(), rows2.size());
  for (size_t i = 0; i < rows1.size(); ++i) {
    if (seconds < rows1[i].size()) rows1[i][seconds].clear();
    if (seconds < rows2[i].size()) rows2[i][seconds].clear();
    EXPECT_EQ(rows1[i], rows2[i]) << "row " << i;
  }
  EXPECT_EQ(test::readFileText(out1 / "table.csv"), test::readFileText(out2 / "table.csv"));
  EXPECT_TRUE(test::readFileText(out1 / "rmse_boxplot.png") == png);
}

// --odometry-dir: each log's trajectory from D/<log id>.tum (here town 1's ground truth, given in
// the city frame); town 2 has no file: its row carries the error and one stderr line names it.
TEST_F(EvalCommand, OdometryDirGivesEachLogItsTrajectoryAndReportsALogWithout) {
  const fs::path odometry = dir_->parent_path() / (dir_->filename().string() + "_odometry");
  fs::create_directories(odometry);
  std::string town1;
  for (const auto& entry : fs::directory_iterator(*dir_ / "town1")) town1 = entry.path().filename().string();
  ASSERT_FALSE(town1.empty());
  const auto made = test::runHdprior("degrade-trajectory " + (*dir_ / "town1" / town1).string() + " --out " +
                                     (odometry / (town1 + ".tum")).string());
  ASSERT_EQ(made.status, 0) << made.err;

  const fs::path out = dir_->parent_path() / (dir_->filename().string() + "_given");
  const auto r = test::runHdprior("eval " + dir_->string() + " --out " + out.string() + " -j 2 --no-prior --odometry-dir " +
                                  odometry.string() + " --odometry-frame city");
  EXPECT_EQ(r.status, 2) << r.err;
  size_t errors = 0;
  for (const std::string& line : split(r.err, '\n')) {
    if (line.rfind("hdprior eval: ", 0) != 0) continue;
    ++errors;
    if (line.find("log broken: ") != std::string::npos) continue;
    EXPECT_NE(line.find(": no trajectory for this log (--odometry-dir needs <log id>.tum or <log id>.txt)"), std::string::npos) << line;
  }
  EXPECT_EQ(errors, 2u) << r.err;  // town 2 and the broken log

  const auto rows = perLogRows(out);
  ASSERT_EQ(rows.size(), 4u);
  const size_t error = column(rows[0], "error"), odoMax = column(rows[0], "odometry_ate_max_m");
  size_t good = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][0] == town1) {
      ++good;
      EXPECT_TRUE(field(rows[i], error).empty()) << field(rows[i], error);
      EXPECT_LT(std::stod(field(rows[i], odoMax)), 1e-5);  // the ground truth, given
    } else if (rows[i][0] != "broken") {
      EXPECT_NE(field(rows[i], error).find(rows[i][0] + ".tum: no trajectory for this log"), std::string::npos) << field(rows[i], error);
      EXPECT_FALSE(fs::exists(out / rows[i][0]));
    }
  }
  EXPECT_EQ(good, 1u);

  // A folder that is not there: one line, nothing written.
  const auto bad = test::runHdprior("eval " + dir_->string() + " --out " + (out.string() + "_x") + " --odometry-dir " +
                                    (odometry / "missing").string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("option --odometry-dir: '" + (odometry / "missing").string() + "' is not a folder"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(out.string() + "_x"));
}

// Logs sorted by path: broken (0), town1 (1), town2 (2); shard 0/2 has broken and town2, 1/2 town1.
// Two shards and a merge give what one eval gives; resubmitting with --skip-existing redoes only the
// broken log.
TEST_F(EvalCommand, ShardsThenMergeGiveOneEvalsResultsAndSkipExistingRedoesOnlyTheFailed) {
  const std::string base = dir_->string();
  const fs::path whole = base + "_whole", sharded = base + "_sharded";
  const auto plain = test::runHdprior("eval " + dir_->string() + " --out " + whole.string() + " -j 2");
  EXPECT_EQ(plain.status, 2) << plain.err;

  const auto shard0 = test::runHdprior("eval " + dir_->string() + " --out " + sharded.string() + " --shard 0/2 -j 2");
  EXPECT_EQ(shard0.status, 2) << shard0.err;  // the broken log is in it
  EXPECT_NE(shard0.out.find("shard 0/2: 2 logs, 1 failed"), std::string::npos) << shard0.out;
  EXPECT_EQ(logLines(shard0.err, "eval").size(), 1u) << shard0.err;
  EXPECT_FALSE(fs::exists(sharded / "per_log.csv"));  // a shard writes no table
  const auto shard1 = test::runHdprior("eval " + dir_->string() + " --out " + sharded.string() + " --shard 1/2");
  EXPECT_EQ(shard1.status, 0) << shard1.err;
  EXPECT_NE(shard1.out.find("shard 1/2: 1 log, 0 failed"), std::string::npos) << shard1.out;

  const auto merged = test::runHdprior("merge " + sharded.string() + " --logs " + dir_->string());
  EXPECT_EQ(merged.status, 2) << merged.err;
  const auto failed = logLines(merged.err, "merge");
  ASSERT_EQ(failed.size(), 1u) << merged.err;
  EXPECT_NE(failed.begin()->second.find("broken/city_SE3_egovehicle.feather"), std::string::npos) << merged.err;
  EXPECT_EQ(perLogWithoutTimes(sharded), perLogWithoutTimes(whole));
  EXPECT_EQ(test::readFileText(sharded / "table.csv"), test::readFileText(whole / "table.csv"));
  EXPECT_EQ(test::readFileText(sharded / "table.md"), test::readFileText(whole / "table.md"));
  EXPECT_TRUE(test::readFileText(sharded / "rmse_boxplot.png") == test::readFileText(whole / "rmse_boxplot.png"));
  EXPECT_NE(merged.out.find("| with HD-map priors | 2 |"), std::string::npos) << merged.out;
  expectNothingTemporary(sharded);

  // Resubmitted: the two logs that went through are kept as they are, the broken one runs again.
  std::map<std::string, fs::file_time_type> written;
  const auto rows = perLogRows(sharded);
  for (size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][0] != "broken") written[rows[i][0]] = fs::last_write_time(sharded / rows[i][0] / "metrics.json");
  }
  ASSERT_EQ(written.size(), 2u);
  const std::string before = test::readFileText(sharded / "per_log.csv");
  for (const char* shard : {"0/2", "1/2"}) {
    const auto again = test::runHdprior("eval " + dir_->string() + " --out " + sharded.string() + " --skip-existing --shard " + shard);
    EXPECT_EQ(again.status, std::string(shard) == "0/2" ? 2 : 0) << again.err;
    EXPECT_NE(again.err.find("went through before, kept (--skip-existing)"), std::string::npos) << again.err;
    EXPECT_EQ(logLines(again.err, "eval").count("broken"), std::string(shard) == "0/2" ? 1u : 0u) << again.err;
  }
  for (const auto& [id, time] : written) EXPECT_EQ(fs::last_write_time(sharded / id / "metrics.json"), time) << id;
  EXPECT_EQ(test::runHdprior("merge " + sharded.string() + " --logs " + dir_->string()).status, 2);
  EXPECT_EQ(test::readFileText(sharded / "per_log.csv"), before);  // the kept logs' times too
}

// A merge before every shard is done: each log without a result is named and counted as failed.
TEST_F(EvalCommand, MergeNamesEveryMissingLog) {
  const fs::path out = dir_->parent_path() / (dir_->filename().string() + "_partly");
  const auto shard1 = test::runHdprior("eval " + dir_->string() + " --out " + out.string() + " --shard 1/2");
  ASSERT_EQ(shard1.status, 0) << shard1.err;
  const auto merged = test::runHdprior("merge " + out.string() + " --logs " + dir_->string());
  EXPECT_EQ(merged.status, 2) << merged.err;
  const auto lines = logLines(merged.err, "merge");
  ASSERT_EQ(lines.size(), 2u) << merged.err;  // broken and town 2: shard 0 never ran
  for (const auto& [id, line] : lines) {
    EXPECT_NE(line.find(": missing: no " + (out / (id + ".result.json")).string()), std::string::npos) << line;
  }
  EXPECT_TRUE(lines.count("broken"));
  const auto table = split(test::readFileText(out / "table.csv"), '\n');
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(split(table[1], ',')[1], "1");  // one log averaged
  EXPECT_EQ(split(table[1], ',')[2], "2");  // two counted as failed
}

// Only broken logs: every table is written, with no average in it, and the status is 2.
TEST(EvalCommandAllFailed, TablesSayNoLogWentThrough) {
  const fs::path dir = test::freshOutputDir("eval_all_failed");
  for (const char* name : {"broken1", "broken2"}) {
    fs::create_directories(dir / "logs" / name / "sensors" / "lidar");
    std::ofstream(dir / "logs" / name / "city_SE3_egovehicle.feather", std::ios::binary) << "ARROW1";
  }
  const auto r = test::runHdprior("eval " + (dir / "logs").string() + " --out " + (dir / "out").string() + " -j 1");
  EXPECT_EQ(r.status, 2) << r.err;
  const std::string md = test::readFileText(dir / "out" / "table.md");
  EXPECT_NE(md.find("No log went through (2 of 2 failed"), std::string::npos) << md;
  EXPECT_NE(md.find("| odometry | 0 | n/a | n/a | n/a | n/a | n/a |"), std::string::npos) << md;
  EXPECT_NE(r.out.find("n/a"), std::string::npos) << r.out;
  const auto table = split(test::readFileText(dir / "out" / "table.csv"), '\n');
  ASSERT_EQ(table.size(), 2u);
  EXPECT_EQ(table[1], "odometry,0,2,,,,,,,,no log went through");
  EXPECT_TRUE(fs::exists(dir / "out" / "rmse_boxplot.png"));
}

TEST(EvalCommandOptions, BadOptionsAreOneLineExit2) {
  const fs::path dir = test::freshOutputDir("eval_options");
  const fs::path empty = dir / "empty", out = dir / "out";
  fs::create_directories(empty);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"eval --out " + out.string(), "argument DIR: is required"},
      {"eval " + (dir / "missing").string() + " --out " + out.string(), "missing: folder not found"},
      {"eval " + empty.string() + " --out " + out.string(), "empty: no Argoverse 2 logs under it"},
      {"eval " + empty.string() + " --out " + out.string() + " -j x", "option --jobs: 'x' is not an integer"},
      {"eval " + empty.string() + " --out " + out.string() + " -j 0", "option --jobs: must be at least 1"},
      {"eval " + empty.string() + " -j 2", "option --out: is required"},
      {"eval " + empty.string() + " --out " + out.string() + " --shard 2/2", "option --shard: '2/2': I must be below N"},
      {"eval " + empty.string() + " --out " + out.string() + " --shard 0/0", "option --shard: '0/0': N must be at least 1"},
      {"eval " + empty.string() + " --out " + out.string() + " --shard 1", "option --shard: '1' is not I/N"},
      {"eval " + empty.string() + " --out " + out.string() + " --shard -1/2", "option --shard: '-1/2' is not I/N"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = test::runHdprior(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("hdprior eval: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << " -> " << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace hdprior

namespace hdprior {

// merge's bad input: one line naming the folder, file or option, status 2, no table written.
TEST(MergeCommand, BadInputIsOneLineExit2AndWritesNothing) {
  const fs::path dir = test::freshOutputDir("merge_bad_input");
  fs::create_directories(dir / "logs" / "broken1" / "sensors" / "lidar");
  std::ofstream(dir / "logs" / "broken1" / "city_SE3_egovehicle.feather", std::ios::binary) << "ARROW1";
  const fs::path out = dir / "out", logs = dir / "logs", result = out / "broken1.result.json";
  fs::create_directories(out);
  const std::string merge = "merge " + out.string() + " --logs " + logs.string();
  // Arguments, the result file's text (none: no file), the message.
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"merge " + (dir / "nothing").string() + " --logs " + logs.string(), "", (dir / "nothing").string() + ": folder not found"},
      {"merge " + out.string(), "", "option --logs: is required"},
      {"merge " + out.string() + " --logs " + (dir / "nologs").string(), "", "nologs: folder not found"},
      {merge, "{\"log\": \"broken1\"", result.string() + ": invalid JSON"},
      {merge, "{\"log\": \"broken1\", \"path\": \"/x\"}", result.string() + ": the result has no 'error'"},
      {merge, "{\"log\": \"other\", \"path\": \"/x\", \"error\": \"x\"}",
       result.string() + ": holds the result of log 'other', not of 'broken1'"},
  };
  for (const auto& [args, text, message] : cases) {
    fs::remove(result);
    if (!text.empty()) std::ofstream(result) << text;
    const auto r = test::runHdprior(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("hdprior merge: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << " -> " << r.err;
  }
  for (const auto& entry : fs::directory_iterator(out)) EXPECT_EQ(entry.path(), result);  // nothing written
}

}  // namespace hdprior
