#include <gtest/gtest.h>

#include "engine/error.h"
#include "engine/pipeline/config.h"

namespace hdprior {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseConfig(text, "my.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Config, DefaultsRoundTripThroughJson) {
  const Config defaults;
  const Config back = parseConfig(formatConfig(defaults), "defaults.json");
  EXPECT_EQ(formatConfig(back), formatConfig(defaults));
  EXPECT_DOUBLE_EQ(back.keyframes.distance, 2.0);
  EXPECT_DOUBLE_EQ(back.keyframes.rotationDeg, 10.0);
  EXPECT_EQ(back.odometry.deskew.mode, "none");
}

TEST(Config, ReadsNestedValuesAndKeepsReservedSections) {
  const Config c = parseConfig(R"({"odometry": {"features": {"edge_curvature": 0.05}, "registration": {"scan_to_scan_guess": true},
                                   "deskew": {"mode": "constant_velocity"}},
                                   "keyframes": {"distance": 3.5}, "match": {"resolution": 1.0}})",
                               "c.json");
  EXPECT_DOUBLE_EQ(c.odometry.features.edgeCurvature, 0.05);
  EXPECT_TRUE(c.odometry.registration.scanToScanGuess);
  EXPECT_EQ(c.odometry.deskew.mode, "constant_velocity");
  EXPECT_DOUBLE_EQ(c.keyframes.distance, 3.5);
  EXPECT_DOUBLE_EQ(c.keyframes.rotationDeg, 10.0);
  EXPECT_NE(formatConfig(c).find("\"resolution\": 1.0"), std::string::npos);
}

TEST(Config, UnknownKeysAndBadValuesNameFileAndKey) {
  EXPECT_EQ(errorOf(R"({"odometry": {"features": {"edge_curvatur": 0.05}}})"), "my.json: unknown key odometry.features.edge_curvatur");
  EXPECT_EQ(errorOf(R"({"odometr": {}})"), "my.json: unknown key odometr");
  EXPECT_EQ(errorOf(R"({"keyframes": {"distance": -1}})"), "my.json: keyframes.distance = -1 is out of range [0.0, 100000.0]");
  EXPECT_NE(errorOf(R"({"odometry": {"local_map": {"max_points_per_voxel": 2.5}}})").find("odometry.local_map.max_points_per_voxel is not an integer"), std::string::npos);
  EXPECT_NE(errorOf(R"({"odometry": {"deskew": {"mode": "magic"}}})").find("odometry.deskew.mode"), std::string::npos);
  EXPECT_NE(errorOf(R"({"match": 3})").find("match must be a JSON object"), std::string::npos);
  EXPECT_NE(errorOf("{").find("invalid JSON"), std::string::npos);
}

}  // namespace hdprior
