// `hdprior match` on the real shared log: JSON output, convergence from an offset start,
// and one-line errors with exit status 2 for bad options.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "test_data.h"

namespace hdprior {
namespace {

TEST(MatchCommand, PrintsTheMatchAsJson) {
  const test::CommandResult r = test::runHdprior("match '" + test::sharedLog().string() + "' --frame 1 --init 0.5,1.5,3 --time-budget 10000");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frame"], 1);
  EXPECT_EQ(j["backend"], "ndt2d");
  EXPECT_GT(j["road_points"].get<int>(), 1000);
  EXPECT_LT(std::abs(j["error"]["lateral"].get<double>()), 0.25);
  EXPECT_LT(std::abs(j["error"]["yaw_deg"].get<double>()), 0.5);
  // The road points reach the mapped kerbs (they follow the camber) and the junction ahead bounds the
  // along-track position: every direction is observed, each sigma covering its error.
  EXPECT_EQ(j["observable_directions"].get<int>(), 3) << j["status"];
  const double lateralHalfWidth = j["evidence_half_widths"]["lateral"].get<double>();
  EXPECT_GT(lateralHalfWidth, 0.1);
  EXPECT_LT(lateralHalfWidth, 1.0);
  for (const char* direction : {"along", "lateral", "yaw_deg"}) {
    ASSERT_FALSE(j["sigma"][direction].is_null()) << direction;
    EXPECT_LE(std::abs(j["error"][direction].get<double>()), 3.0 * j["sigma"][direction].get<double>()) << direction;
  }
  EXPECT_GT(j["iterations"].get<int>(), 0);
  EXPECT_GT(j["time_ms"].get<double>(), 0.0);
  ASSERT_EQ(j["covariance_x_y_yaw"].size(), 3u);
  ASSERT_EQ(j["information_x_y_yaw"].size(), 3u);
  // The initial pose is the truth moved 0.5 m forward, 1.5 m left, 3 degrees.
  EXPECT_NEAR(j["initial"]["yaw_deg"].get<double>() - j["truth"]["yaw_deg"].get<double>(), 3.0, 1e-3);
}

TEST(MatchCommand, PclBackendIsSelectable) {
  const test::CommandResult r = test::runHdprior("match '" + test::sharedLog().string() + "' --frame 1 --backend pcl");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["backend"], "pcl");
  EXPECT_LT(std::abs(j["error"]["lateral"].get<double>()), 0.5);
}

TEST(MatchCommand, BadOptionsGiveOneLineAndStatusTwo) {
  const std::string log = "'" + test::sharedLog().string() + "'";
  for (const std::string& args : {log + " --frame 2", log + " --frame -1", log, log + " --frame 0 --init 1,2",
                                  log + " --frame 0 --init a,b,c", log + " --frame 0 --backend gicp",
                                  log + " --frame 0 --time-budget 0",
                                  std::string("/nonexistent --frame 0")}) {
    const test::CommandResult r = test::runHdprior("match " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace hdprior
