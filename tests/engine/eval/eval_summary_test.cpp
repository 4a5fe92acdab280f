#include <gtest/gtest.h>

#include <limits>
#include <sstream>

#include "engine/eval/eval_report.h"
#include "engine/eval/eval_summary.h"

namespace hdprior {
namespace {

TrajectoryEvaluation evaluation(double mean, double median, double rmse, double std, double max) {
  TrajectoryEvaluation e;
  e.ate.translation = {.count = 100, .mean = mean, .median = median, .rmse = rmse, .std = std, .max = max};
  e.ate.along.rmse = rmse / 4;
  e.ate.lateral.rmse = rmse / 2;
  e.pathLength = 80;
  e.rpe10 = {.length = 10, .segments = 5, .translationPercent = 0.5};
  return e;
}

LogEvaluation okLog(const std::string& id, double scale, bool priors) {
  LogEvaluation l;
  l.id = id;
  l.path = "/logs/" + id;
  l.sweeps = 100;
  l.odometry = evaluation(1 * scale, 2 * scale, 3 * scale, 4 * scale, 5 * scale);
  if (priors) l.optimized = evaluation(0.1 * scale, 0.2 * scale, 0.3 * scale, 0.4 * scale, 0.5 * scale);
  l.matchesAccepted = 3;
  l.pipelineSeconds = 4.5;
  return l;
}

LogEvaluation failedLog(const std::string& id, const std::string& error) {
  LogEvaluation l;
  l.id = id;
  l.path = "/logs/" + id;
  l.error = error;
  return l;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

TEST(EvalSummary, AveragesEachStatisticOverTheLogsThatWentThrough) {
  const std::vector<LogEvaluation> logs = {okLog("a", 1, true), failedLog("b", "x: broken"), okLog("c", 2, true),
                                           okLog("d", 6, true)};
  const EvalSummary s = summarizeLogs(logs);
  EXPECT_EQ(s.logs, 4u);
  EXPECT_EQ(s.failed, 1u);
  EXPECT_EQ(s.odometry.count, 3u);
  EXPECT_DOUBLE_EQ(s.odometry.mean, (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.odometry.median, 2 * (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.odometry.rmse, 3 * (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.odometry.std, 4 * (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.odometry.max, 5 * (1 + 2 + 6) / 3.0);
  ASSERT_TRUE(s.optimized.has_value());
  EXPECT_EQ(s.optimized->count, 3u);
  EXPECT_DOUBLE_EQ(s.optimized->rmse, 0.3 * (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.odometrySplit.along, 3.0 / 4 * (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.odometrySplit.lateral, 3.0 / 2 * (1 + 2 + 6) / 3.0);
  EXPECT_DOUBLE_EQ(s.optimizedSplit.lateral, 0.3 / 2 * (1 + 2 + 6) / 3.0);
}

TEST(EvalSummary, WithoutPriorsOnlyTheOdometryAndAllFailedGivesNothing) {
  const EvalSummary odo = summarizeLogs({okLog("a", 1, false), okLog("b", 3, false)});
  EXPECT_FALSE(odo.optimized.has_value());
  EXPECT_DOUBLE_EQ(odo.odometry.rmse, 6.0);
  const EvalSummary none = summarizeLogs({failedLog("a", "e")});
  EXPECT_EQ(none.failed, 1u);
  EXPECT_EQ(none.odometry.count, 0u);
  EXPECT_FALSE(none.optimized.has_value());
}

TEST(EvalReport, PerLogCsvHasARowPerLogAndQuotesTheError) {
  LogEvaluation a = okLog("a", 1, true);
  a.skippedSweeps = {"/logs/a/sensors/lidar/5.feather: file too short"};
  const std::string csv = perLogCsv({a, failedLog("b", "b/city_SE3_egovehicle.feather: file too short, \"12\" bytes"),
                                     okLog("c", 2, false)});
  const auto rows = lines(csv);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].rfind("log_id,path,sweeps,skipped_sweeps,path_length_m,odometry_ate_mean_m,", 0), 0u);
  EXPECT_NE(rows[0].find(",optimized_ate_rmse_m,"), std::string::npos);
  EXPECT_EQ(rows[1].rfind("a,/logs/a,100,1,80.000,1.000000,2.000000,3.000000,4.000000,5.000000,0.750000,1.500000,0.500000,,"
                          "0.100000,0.200000,0.300000,0.400000,0.500000,0.075000,0.150000,0.500000,,3,0,0,,,,,,,4.50,", 0), 0u)
      << rows[1];
  EXPECT_EQ(rows[2], "b,/logs/b,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,\"b/city_SE3_egovehicle.feather: file too short, \"\"12\"\" bytes\"");
  // Without priors the optimised columns, the match counts and the prior calibration are empty.
  EXPECT_NE(rows[3].find(",0.500000,,,,,,,,,,,,,,,,,,,,4.50,"), std::string::npos) << rows[3];
  const size_t columns = std::count(rows[0].begin(), rows[0].end(), ',');
  EXPECT_EQ(std::count(rows[1].begin(), rows[1].end(), ','), long(columns));
  EXPECT_EQ(std::count(rows[3].begin(), rows[3].end(), ','), long(columns));
}

TEST(EvalReport, TablesStateTheAveraging) {
  const EvalSummary s = summarizeLogs({okLog("a", 1, true), failedLog("b", "e"), okLog("c", 2, true)});
  const std::string md = summaryMarkdown(s);
  EXPECT_NE(md.find("average over the 2 logs that went through (of 3; 1 failed)"), std::string::npos) << md;
  EXPECT_NE(md.find("| odometry | 2 | 1.500 | 3.000 | 4.500 | 6.000 | 7.500 | 1.125 | 2.250 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| with HD-map priors | 2 | 0.150 | 0.300 | 0.450 | 0.600 | 0.750 | 0.112 | 0.225 |"), std::string::npos) << md;
  EXPECT_NE(summaryMarkdown(summarizeLogs({okLog("a", 1, true)})).find("over the 1 log that went through (of 1; 0 failed)"),
            std::string::npos);
  const auto rows = lines(summaryCsv(s));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], "trajectory,logs,failed_logs,mean_m,median_m,rmse_m,std_m,max_m,along_rmse_m,lateral_rmse_m,averaging");
  EXPECT_EQ(rows[1].rfind("odometry,2,1,1.500000,3.000000,4.500000,6.000000,7.500000,1.125000,2.250000,", 0), 0u) << rows[1];
}

// Every log failed: no average is 0.000; table.md says no log went through and shows n/a,
// table.csv leaves the statistics empty (missing values to a CSV reader).
TEST(EvalReport, WhenNoLogWentThroughTheTablesShowNoAverage) {
  const EvalSummary s = summarizeLogs({failedLog("a", "x: broken"), failedLog("b", "y: broken")});
  const std::string md = summaryMarkdown(s);
  EXPECT_NE(md.find("No log went through (2 of 2 failed; per_log.csv has each one's error)"), std::string::npos) << md;
  EXPECT_NE(md.find("| odometry | 0 | n/a | n/a | n/a | n/a | n/a | n/a | n/a |"), std::string::npos) << md;
  EXPECT_EQ(md.find("0.000"), std::string::npos) << md;
  const auto rows = lines(summaryCsv(s));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1], "odometry,0,2,,,,,,,,no log went through");
}

TEST(EvalReport, BoxPlotOfTheSuccessfulLogs) {
  const RgbImage im = rmseBoxPlot({okLog("a", 1, true), failedLog("b", "e"), okLog("c", 2, true)});
  EXPECT_EQ(im.width, 720);
  EXPECT_EQ(im.height, 540);
  EXPECT_EQ(im.rgb.size(), size_t(720 * 540 * 3));
}

// The priors' errors are pooled over the logs: per_log.csv has each log's, table.md the pooled
// calibration and how many logs the priors made more than 10 % worse.
TEST(EvalReport, PriorCalibrationIsPerLogAndPooled) {
  LogEvaluation a = okLog("a", 1, true), b = okLog("b", 1, true);
  const double inf = std::numeric_limits<double>::infinity();
  a.priorErrors = {{{0.5, 0.1, 0.001}, {inf, 0.1, 0.01}}, {{0.5, -0.4, 0.001}, {inf, 0.1, 0.01}}};
  b.priorErrors = {{{0.5, 0.2, 0.001}, {inf, 0.1, inf}}};
  b.optimized->ate.translation.rmse = 4.0;  // worse than its odometry's 3.0
  const auto rows = lines(perLogCsv({a, b}));
  // a: lateral RMS sqrt((0.01 + 0.16) / 2), one of two beyond 3 sigma, median NEES (1 + 16) / 2.
  EXPECT_NE(rows[1].find(",0.291548,0.500000,8.500000,"), std::string::npos) << rows[1];
  const EvalSummary s = summarizeLogs({a, b});
  EXPECT_EQ(s.priors.matches, 3u);
  EXPECT_EQ(s.priors.along.observed, 0u);
  EXPECT_EQ(s.priors.lateral.observed, 3u);
  EXPECT_EQ(s.priors.yaw.observed, 2u);
  EXPECT_NEAR(s.priors.lateral.beyond3Sigma, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.priors.lateral.medianNees, 4.0, 1e-12);
  EXPECT_EQ(s.logsWorse, 1u);
  EXPECT_NEAR(s.worstRatio, 4.0 / 3.0, 1e-12);
  const std::string md = summaryMarkdown(s);
  EXPECT_NE(md.find("| lateral | 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("more than 10 % above the odometry's: 1 (largest ratio 1.33)"), std::string::npos) << md;
}

}  // namespace hdprior
