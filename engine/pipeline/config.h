#pragma once
#include <filesystem>
#include <string>

#include "engine/graph/pose_graph.h"
#include "engine/graph/pose_prior.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/match/match_options.h"
#include "engine/odom/odometry_options.h"

namespace hdprior {

// The one configuration tree of hdprior, read by the CLI and the app from one JSON file. Every key
// is optional: a file's keys are set over the defaults, assets/default_config.json (embedded at
// build time: defaultConfig()). Unknown keys and out-of-range values are errors naming the file and
// the key. The structs' own initialisers equal that file (DefaultConfig tests keep them so), for
// code that uses an option struct without a configuration.
//
// {
//   "odometry": {"features": {...}, "deskew": {"mode": "none"}, "registration": {...}, "local_map": {...},
//                "drift": {"scale": 0, "yaw_deg_per_100m": 0, "pitch_deg_per_100m": 0}},
//   "keyframes": {"distance": 2.0, "rotation_deg": 10.0},
//   "road_points": {"ground": {...}, "road": {...}, "thin_cell": 0.1},
//   "match": {"backend": "ndt2d", "cell_sizes": [4, 2, 1], ...},
//   "prior": {"ego_height": 0.32, "altitude_sigma": 0.1},
//   "graph": {"prior_huber": 1.0, ..., "odometry_translation_sigma_per_m": ..., "odometry_rotation_sigma_deg_per_m": ...},
//   "sweeps": {"max_unreadable_share": 0.05}
// }
struct Config {
  OdometryOptions odometry;
  KeyframeOptions keyframes;
  SweepRoadPointOptions roadPoints;
  MatchOptions match;
  PosePriorOptions prior;
  PoseGraphOptions graph;
  // Unreadable sweeps are skipped; more than this share of the log's sweeps fails the log.
  double maxUnreadableSweepShare = 0.05;
};

// The built-in default configuration: the text of assets/default_config.json, and that text parsed.
const std::string& defaultConfigText();
const Config& defaultConfig();

Config parseConfig(const std::string& jsonText, const std::string& source);  // its keys over defaultConfig()
std::string formatConfig(const Config& config);  // pretty JSON with every key
Config loadConfig(const std::filesystem::path& path);
void saveConfig(const std::filesystem::path& path, const Config& config);

}  // namespace hdprior
