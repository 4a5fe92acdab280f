#include <gtest/gtest.h>

#include "engine/error.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/config_schema.h"
#include "error_message.h"

#include <cstdlib>
#include <nlohmann/json.hpp>

namespace hdprior {
namespace {

// The message parsing `text` as my.json fails with, or "" when it is accepted.
std::string configErrorOf(const std::string& text) { return test::errorOf([&] { parseConfig(text, "my.json"); }); }

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
  const Config c = parseConfig(R"({"vehicle": {"ego_height": 0.4},
                                   "odometry": {"features": {"plane_curvature": 0.05}, "registration": {"threads": 1},
                                   "deskew": {"mode": "constant_velocity"}},
                                   "keyframes": {"distance": 3.5},
                                   "road_points": {"thin_cell": 0.2, "ground": {"seed_height": 0.3},
                                                   "road": {"max_step": 0.08}},
                                   "match": {"backend": "pcl", "cell_sizes": [2.0, 1.0], "prediction_sigma": [1, 2, 0.1]},
                                   "graph": {"prior_huber": 2.5}})",
                               "c.json");
  EXPECT_DOUBLE_EQ(c.odometry.features.planeCurvature, 0.05);
  EXPECT_EQ(c.odometry.registration.threads, 1);
  EXPECT_EQ(c.odometry.deskew.mode, "constant_velocity");
  EXPECT_DOUBLE_EQ(c.keyframes.distance, 3.5);
  EXPECT_DOUBLE_EQ(c.keyframes.rotationDeg, 10.0);
  EXPECT_DOUBLE_EQ(c.roadPoints.thinCell, 0.2);
  EXPECT_DOUBLE_EQ(c.roadPoints.ground.seedHeight, 0.3);
  EXPECT_DOUBLE_EQ(c.roadPoints.road.maxStep, 0.08);
  EXPECT_EQ(c.match.backend, MatchBackend::PclNdt);
  EXPECT_EQ(c.match.cellSizes, (std::vector<double>{2.0, 1.0}));
  EXPECT_EQ(c.match.predictionSigma, Eigen::Vector3d(1, 2, 0.1));
  EXPECT_DOUBLE_EQ(c.graph.priorHuber, 2.5);
  const Config back = parseConfig(formatConfig(c), "back.json");
  EXPECT_EQ(formatConfig(back), formatConfig(c));
  EXPECT_NE(formatConfig(c).find("\"backend\": \"pcl\""), std::string::npos);
}

// One key for the ego origin's height: the prior's altitude and the road level of both road-point
// stages follow it.
TEST(Config, OneEgoHeightSetsTheRoadLevel) {
  const Config c = parseConfig(R"({"vehicle": {"ego_height": 1.73}})", "kitti.json");
  EXPECT_DOUBLE_EQ(c.prior.egoHeight, 1.73);
  EXPECT_DOUBLE_EQ(c.roadPoints.ground.groundZ, -1.73);
  EXPECT_DOUBLE_EQ(c.roadPoints.road.groundZ, -1.73);
  EXPECT_EQ(configErrorOf(R"({"road_points": {"ground": {"ground_z": -1.73}}})"), "my.json: unknown key road_points.ground.ground_z");
  EXPECT_EQ(configErrorOf(R"({"prior": {"ego_height": 1.73}})"), "my.json: unknown key prior.ego_height");
}

TEST(Config, UnknownKeysAndBadValuesNameFileAndKey) {
  EXPECT_EQ(configErrorOf(R"({"odometry": {"features": {"plane_curvatur": 0.05}}})"), "my.json: unknown key odometry.features.plane_curvatur");
  EXPECT_EQ(configErrorOf(R"({"odometr": {}})"), "my.json: unknown key odometr");
  EXPECT_EQ(configErrorOf(R"({"keyframes": {"distance": -1}})"), "my.json: keyframes.distance = -1 is out of range [0, 100000]");
  EXPECT_NE(configErrorOf(R"({"odometry": {"local_map": {"max_points_per_voxel": 2.5}}})").find("odometry.local_map.max_points_per_voxel is not an integer"), std::string::npos);
  EXPECT_EQ(configErrorOf(R"({"odometry": {"deskew": {"mode": "magic"}}})"), "my.json: odometry.deskew.mode must be one of none, constant_velocity");
  EXPECT_NE(configErrorOf(R"({"match": 3})").find("match must be a JSON object"), std::string::npos);
  EXPECT_EQ(configErrorOf(R"({"match": {"backend": "icp"}})"), "my.json: match.backend must be one of ndt2d, pcl");
  EXPECT_EQ(configErrorOf(R"({"match": {"cell_sizes": [1.0, 0.0]}})"), "my.json: match.cell_sizes = 0.0 is out of range [0.5, 100]");
  EXPECT_EQ(configErrorOf(R"({"match": {"cell_sizes": []}})"), "my.json: match.cell_sizes must be a non-empty array of numbers");
  EXPECT_EQ(configErrorOf(R"({"match": {"cell_sizes": [1.0, 2.0]}})"), "my.json: match.cell_sizes must go from coarse to fine (decreasing)");
  EXPECT_EQ(configErrorOf(R"({"match": {"prediction_sigma": [1, 1]}})"), "my.json: match.prediction_sigma must be an array of 3 numbers");
  EXPECT_EQ(configErrorOf(R"({"odometry": {"features": {"min_range": 50, "max_range": 40}}})"),
            "my.json: odometry.features.min_range must be below odometry.features.max_range");
  EXPECT_EQ(configErrorOf(R"({"graph": {"unknown": 1}})"), "my.json: unknown key graph.unknown");
  EXPECT_NE(configErrorOf("{").find("invalid JSON"), std::string::npos);
}

// The values the engine's stages refuse are refused when the file is read, naming the file and the key.
TEST(Config, ValuesTheStagesRefuseAreRefusedWhenRead) {
  EXPECT_EQ(configErrorOf(R"({"match": {"min_points": 0}})"), "my.json: match.min_points = 0 is out of range [1, 10000000]");
  EXPECT_EQ(configErrorOf(R"({"match": {"gate_chi2": 0}})"), "my.json: match.gate_chi2 = 0 is out of range (0, 1000000000]");
  EXPECT_EQ(configErrorOf(R"({"match": {"degenerate_ratio": 1}})"), "my.json: match.degenerate_ratio = 1 is out of range [0, 1)");
  EXPECT_EQ(configErrorOf(R"({"match": {"boundary_band": 0}})"), "my.json: match.boundary_band = 0 is out of range (0, 100]");
  EXPECT_EQ(configErrorOf(R"({"match": {"stale_distance": 0}})"), "my.json: match.stale_distance = 0 is out of range (0, 1000]");
  EXPECT_EQ(configErrorOf(R"({"graph": {"prior_huber": 0}})"), "my.json: graph.prior_huber = 0 is out of range (0, 1000000]");
}

// Every key rejects a value just beyond each end of its range, and a value of the wrong type, with
// one message naming the file and the key.
TEST(Config, EveryKeyRejectsValuesBeyondItsRangeNamingFileAndKey) {
  for (const ConfigKey& k : configKeys()) {
    std::string pointer = "/" + k.key;
    for (char& c : pointer) if (c == '.') c = '/';
    const auto fileWith = [&](const nlohmann::json& value) {
      nlohmann::json file = nlohmann::json::object();
      file[nlohmann::json::json_pointer(pointer)] = value;
      return file.dump();
    };
    EXPECT_NE(configErrorOf(fileWith(nlohmann::json::object({{"x", 1}}))).find("my.json: " + k.key), std::string::npos) << k.key;
    if (k.range.front() != '[' && k.range.front() != '(') continue;  // a choice: its names are tested above
    char* end = nullptr;
    const double lo = std::strtod(k.range.c_str() + 1, &end), hi = std::strtod(end + 1, &end);
    const bool array = nlohmann::json::parse(k.defaultValue).is_array();
    for (double beyond : {k.range.front() == '(' ? lo : lo - 1, *end == ')' ? hi : hi + 1}) {
      const nlohmann::json value = array ? nlohmann::json::array({beyond, beyond, beyond}) : nlohmann::json(beyond);
      const std::string error = configErrorOf(fileWith(value));
      EXPECT_EQ(error.rfind("my.json: " + k.key + " ", 0), 0u) << k.key << " = " << beyond << ": " << error;
    }
  }
}

// The odometry drift injected for evaluation is an option of run and eval, not a key.
TEST(Config, TheOdometryDriftIsNotAKey) {
  EXPECT_EQ(configErrorOf(R"({"odometry": {"drift": {"scale": 0.007}}})"), "my.json: unknown key odometry.drift");
  EXPECT_FALSE(Config{}.odometry.drift.active());
}

// The switches that were measured and left off, and the on-switches that are the method, are gone
// with their code paths (docs/experiments/2026-12-06-configuration-pruned.md).
TEST(Config, RemovedSwitchesAreUnknownKeys) {
  for (const char* key : {"odometry.registration.scan_to_scan_guess", "odometry.features.sharp_per_sector", "road_points.submap",
                          "road_points.road.lane_seeds", "match.lookup", "match.evidence_spill_share", "match.curb_refinement",
                          "match.stale_regions", "match.evidence_uncertainty", "prior.along_track", "graph.odometry_scale_sigma",
                          "graph.odometry_yaw_drift_sigma_deg_per_100m", "graph.estimate_drift_model", "graph.fix_first"}) {
    std::string pointer = std::string("/") + key;
    for (char& c : pointer) if (c == '.') c = '/';
    nlohmann::json file = nlohmann::json::object();
    file[nlohmann::json::json_pointer(pointer)] = true;
    EXPECT_EQ(configErrorOf(file.dump()), std::string("my.json: unknown key ") + key);
  }
}

TEST(Config, TheGraphsDriftModel) {
  const Config c = parseConfig(R"({"graph": {"odometry_translation_sigma_per_m": 0.01, "odometry_rotation_sigma_deg_per_m": 0.02}})",
                               "c.json");
  EXPECT_DOUBLE_EQ(c.graph.odometryTranslationSigmaPerM, 0.01);
  EXPECT_DOUBLE_EQ(c.graph.odometryRotationSigmaDegPerM, 0.02);
  EXPECT_EQ(formatConfig(parseConfig(formatConfig(c), "back.json")), formatConfig(c));
  EXPECT_EQ(configErrorOf(R"({"graph": {"odometry_translation_sigma_per_m": -0.1}})"),
            "my.json: graph.odometry_translation_sigma_per_m = -0.1 is out of range (0, 10]");
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
  EXPECT_EQ(configErrorOf(R"({"graph": {"given_odometry_rotation_sigma_deg_per_m": 200}})"),
            "my.json: graph.given_odometry_rotation_sigma_deg_per_m = 200 is out of range (0, 180]");
}

}  // namespace hdprior
