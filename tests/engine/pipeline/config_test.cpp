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

TEST(Config, ReadsNestedValuesOfEveryStage) {
  const Config c = parseConfig(R"({"odometry": {"features": {"edge_curvature": 0.05}, "registration": {"scan_to_scan_guess": true},
                                   "deskew": {"mode": "constant_velocity"}},
                                   "keyframes": {"distance": 3.5},
                                   "road_points": {"thin_cell": 0.2, "ground": {"zone_rings": [2, 2, 2, 2]},
                                                   "road": {"max_step": 0.08}},
                                   "match": {"backend": "pcl", "cell_sizes": [2.0, 1.0],
                                             "prediction_sigma": [1, 2, 0.1]},
                                   "prior": {"ego_height": 0.4}, "graph": {"prior_huber": 2.5}})",
                               "c.json");
  EXPECT_DOUBLE_EQ(c.odometry.features.edgeCurvature, 0.05);
  EXPECT_TRUE(c.odometry.registration.scanToScanGuess);
  EXPECT_EQ(c.odometry.deskew.mode, "constant_velocity");
  EXPECT_DOUBLE_EQ(c.keyframes.distance, 3.5);
  EXPECT_DOUBLE_EQ(c.keyframes.rotationDeg, 10.0);
  EXPECT_DOUBLE_EQ(c.roadPoints.thinCell, 0.2);
  EXPECT_EQ(c.roadPoints.ground.zoneRings, (std::vector<int>{2, 2, 2, 2}));
  EXPECT_DOUBLE_EQ(c.roadPoints.road.maxStep, 0.08);
  EXPECT_EQ(c.match.backend, MatchBackend::PclNdt);
  EXPECT_EQ(c.match.cellSizes, (std::vector<double>{2.0, 1.0}));
  EXPECT_EQ(c.match.predictionSigma, Eigen::Vector3d(1, 2, 0.1));
  EXPECT_DOUBLE_EQ(c.prior.egoHeight, 0.4);
  EXPECT_DOUBLE_EQ(c.graph.priorHuber, 2.5);
  const Config back = parseConfig(formatConfig(c), "back.json");
  EXPECT_EQ(formatConfig(back), formatConfig(c));
  EXPECT_NE(formatConfig(c).find("\"backend\": \"pcl\""), std::string::npos);
}

TEST(Config, UnknownKeysAndBadValuesNameFileAndKey) {
  EXPECT_EQ(errorOf(R"({"odometry": {"features": {"edge_curvatur": 0.05}}})"), "my.json: unknown key odometry.features.edge_curvatur");
  EXPECT_EQ(errorOf(R"({"match": {"lookup": "bilinear"}})"), "my.json: unknown key match.lookup");
  EXPECT_EQ(errorOf(R"({"odometr": {}})"), "my.json: unknown key odometr");
  EXPECT_EQ(errorOf(R"({"keyframes": {"distance": -1}})"), "my.json: keyframes.distance = -1 is out of range [0.0, 100000.0]");
  EXPECT_NE(errorOf(R"({"odometry": {"local_map": {"max_points_per_voxel": 2.5}}})").find("odometry.local_map.max_points_per_voxel is not an integer"), std::string::npos);
  EXPECT_NE(errorOf(R"({"odometry": {"deskew": {"mode": "magic"}}})").find("odometry.deskew.mode"), std::string::npos);
  EXPECT_NE(errorOf(R"({"match": 3})").find("match must be a JSON object"), std::string::npos);
  EXPECT_EQ(errorOf(R"({"match": {"backend": "icp"}})"), "my.json: match.backend must be \"ndt2d\" or \"pcl\"");
  EXPECT_EQ(errorOf(R"({"match": {"cell_sizes": [1.0, 0.0]}})"), "my.json: match.cell_sizes = 0.0 is out of range [0.1, 100.0]");
  EXPECT_EQ(errorOf(R"({"match": {"cell_sizes": []}})"), "my.json: match.cell_sizes must be a non-empty array of numbers");
  EXPECT_EQ(errorOf(R"({"match": {"cell_sizes": [1.0, 2.0]}})"), "my.json: match.cell_sizes must go from coarse to fine (decreasing)");
  EXPECT_EQ(errorOf(R"({"match": {"prediction_sigma": [1, 1]}})"), "my.json: match.prediction_sigma must be an array of 3 numbers");
  EXPECT_EQ(errorOf(R"({"road_points": {"ground": {"zone_rings": [1, 2]}}})"),
            "my.json: road_points.ground.zone_radii, zone_rings and zone_sectors must have the same length");
  EXPECT_EQ(errorOf(R"({"road_points": {"road": {"lane_object_height": 0.05}}})"),
            "my.json: road_points.road.lane_object_height must be above lane_step");
  EXPECT_EQ(errorOf(R"({"graph": {"unknown": 1}})"), "my.json: unknown key graph.unknown");
  EXPECT_NE(errorOf("{").find("invalid JSON"), std::string::npos);
}

TEST(Config, OdometryDriftAndTheGraphsDriftModel) {
  const Config c = parseConfig(R"({"odometry": {"drift": {"scale": 0.007, "yaw_deg_per_100m": -0.5}},
                                   "graph": {"odometry_translation_sigma_per_m": 0.01, "odometry_rotation_sigma_deg_per_m": 0.02}})",
                               "c.json");
  EXPECT_DOUBLE_EQ(c.odometry.drift.scale, 0.007);
  EXPECT_DOUBLE_EQ(c.odometry.drift.yawDegPer100m, -0.5);
  EXPECT_DOUBLE_EQ(c.odometry.drift.pitchDegPer100m, 0.0);
  EXPECT_DOUBLE_EQ(c.graph.odometryTranslationSigmaPerM, 0.01);
  EXPECT_DOUBLE_EQ(c.graph.odometryRotationSigmaDegPerM, 0.02);
  EXPECT_EQ(formatConfig(parseConfig(formatConfig(c), "back.json")), formatConfig(c));
  EXPECT_NE(formatConfig(c).find("\"yaw_deg_per_100m\": -0.5"), std::string::npos);
  EXPECT_FALSE(Config{}.odometry.drift.active());  // no drift unless asked for
  EXPECT_EQ(errorOf(R"({"odometry": {"drift": {"scale": 0.2}}})"), "my.json: odometry.drift.scale = 0.2 is out of range (-0.2, 0.2)");
  EXPECT_EQ(errorOf(R"({"odometry": {"drift": {"pitch_deg_per_100m": 30}}})"),
            "my.json: odometry.drift.pitch_deg_per_100m = 30 is out of range [-20, 20]");
  EXPECT_EQ(errorOf(R"({"odometry": {"drift": {"roll": 1}}})"), "my.json: unknown key odometry.drift.roll");
  EXPECT_EQ(errorOf(R"({"graph": {"odometry_translation_sigma_per_m": -0.1}})"),
            "my.json: graph.odometry_translation_sigma_per_m = -0.1 is out of range [0.0, 10.0]");
}

TEST(Config, GivenOdometrysDriftModel) {
  const Config defaults;
  EXPECT_DOUBLE_EQ(defaults.graph.givenOdometryTranslationSigmaPerM, 0.01);
  EXPECT_DOUBLE_EQ(defaults.graph.givenOdometryRotationSigmaDegPerM, 0.01);
  const Config c = parseConfig(R"({"graph": {"given_odometry_translation_sigma_per_m": 0.005,
                                             "given_odometry_rotation_sigma_deg_per_m": 0.002}})", "c.json");
  EXPECT_DOUBLE_EQ(c.graph.givenOdometryTranslationSigmaPerM, 0.005);
  EXPECT_DOUBLE_EQ(c.graph.givenOdometryRotationSigmaDegPerM, 0.002);
  EXPECT_EQ(formatConfig(parseConfig(formatConfig(c), "back.json")), formatConfig(c));
  EXPECT_EQ(errorOf(R"({"graph": {"given_odometry_rotation_sigma_deg_per_m": 200}})"),
            "my.json: graph.given_odometry_rotation_sigma_deg_per_m = 200 is out of range [0.0, 180.0]");
}

}  // namespace hdprior
