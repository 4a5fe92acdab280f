#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "engine/error.h"
#include "engine/eval/eval_report.h"
#include "engine/eval/log_evaluation_file.h"
#include "test_data.h"

namespace hdprior {
namespace {

namespace fs = std::filesystem;

// Figures with all 17 significant digits, so a lossy round trip would show.
TrajectoryEvaluation evaluation(double k) {
  TrajectoryEvaluation e;
  e.label = "none";
  e.pathLength = 81.23456789012345 * k;
  e.ate.translation = {.count = 97, .mean = 0.1234567890123457 * k, .median = 0.1 / 3 * k, .rmse = std::sqrt(2.0) * k / 10,
                       .std = 1e-17 * k, .max = std::acos(-1.0) * k};
  e.ate.along.rmse = 0.9 / 7 * k;
  e.ate.lateral.rmse = 0.7 / 3 * k;
  e.rpe10 = {.length = 10, .segments = 7, .translationPercent = 2.0 / 3 * k};
  e.rpe100 = {.length = 100, .segments = 0};
  return e;
}

LogEvaluation okLog() {
  LogEvaluation l;
  l.id = "log-a";
  l.path = "/data/logs, with a comma/log-a";
  l.sweeps = 40;
  l.skippedSweeps = {"sensors/lidar/1.feather: truncated"};
  l.odometry = evaluation(1);
  l.optimized = evaluation(0.3);
  l.matchesAccepted = 5;
  l.matchesDegenerate = 2;
  l.matchesRejected = 1;
  const double inf = std::numeric_limits<double>::infinity();
  l.priorErrors = {{{0.01 / 3, -0.2 / 7, 0.003}, {0.1, 0.05, 0.01}}, {{1.0 / 3, 0.02, -0.001}, {inf, 0.04, 0.02}}};
  l.pipelineSeconds = 12.345678;
  return l;
}

}  // namespace

TEST(LogEvaluationFile, RoundTripsEveryFigureTheTablesUseExactly) {
  const fs::path file = logEvaluationFile(test::freshOutputDir("log_evaluation_file"), "log-a");
  EXPECT_EQ(file.filename(), "log-a.result.json");
  LogEvaluation failed;
  failed.id = "log-b";
  failed.path = "/data/log-b";
  failed.error = "/data/log-b/city_SE3_egovehicle.feather: truncated";
  const std::vector<LogEvaluation> logs = {okLog(), failed};
  std::vector<LogEvaluation> read;
  for (const LogEvaluation& l : logs) {
    writeLogEvaluation(file, l);
    read.push_back(readLogEvaluation(file));
  }
  EXPECT_EQ(perLogCsv(read), perLogCsv(logs));
  EXPECT_EQ(summaryMarkdown(summarizeLogs(read)), summaryMarkdown(summarizeLogs(logs)));
  EXPECT_EQ(summaryCsv(summarizeLogs(read)), summaryCsv(summarizeLogs(logs)));
  const LogEvaluation& a = read[0];
  EXPECT_EQ(a.skippedSweeps, logs[0].skippedSweeps);
  EXPECT_EQ(a.odometry->ate.translation.mean, logs[0].odometry->ate.translation.mean);  // bit for bit
  EXPECT_EQ(a.optimized->ate.translation.max, logs[0].optimized->ate.translation.max);
  EXPECT_EQ(a.priorErrors[0].error, logs[0].priorErrors[0].error);
  EXPECT_TRUE(std::isinf(a.priorErrors[1].sigma(0)));  // unobservable stays unobservable
  EXPECT_EQ(a.pipelineSeconds, logs[0].pipelineSeconds);
  EXPECT_FALSE(read[1].ok());
  EXPECT_EQ(read[1].error, failed.error);
  for (const auto& entry : fs::directory_iterator(file.parent_path())) EXPECT_EQ(entry.path(), file);  // no temporary left
}

TEST(LogEvaluationFile, ACorruptFileIsAnErrorNamingItAndTheProblem) {
  const fs::path dir = test::freshOutputDir("log_evaluation_file_corrupt");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"log\": \"x\", \"path\": \"/x\"", "invalid JSON"},
      {"{\"log\": \"x\", \"path\": \"/x\"}", "has no 'error'"},
      {"{\"log\": \"x\", \"path\": \"/x\", \"error\": \"\", \"sweeps\": -3}", "sweeps is negative"},
      {"{\"log\": \"x\", \"path\": \"/x\", \"error\": \"\", \"sweeps\": 3, \"skipped_sweeps\": [], \"matches\": "
       "{\"accepted\": 1, \"degenerate\": 0, \"rejected\": 0}, \"prior_errors\": [{\"error\": [1, 2], \"sigma\": [1, 2, 3]}], "
       "\"pipeline_s\": 1}",
       "does not have 3 numbers"},
      {"[]", "is not an object"},
  };
  for (const auto& [text, problem] : cases) {
    const fs::path file = dir / "x.result.json";
    std::ofstream(file) << text;
    try {
      readLogEvaluation(file);
      ADD_FAILURE() << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), file.string());
      EXPECT_NE(e.reason().find(problem), std::string::npos) << text << " -> " << e.reason();
    }
  }
  EXPECT_THROW(readLogEvaluation(dir / "missing.result.json"), Error);
}

}  // namespace hdprior
