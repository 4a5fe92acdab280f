#pragma once
#include <filesystem>
#include <string>

#include "engine/odom/odometry_options.h"

namespace hdprior {

// The one configuration tree of hdprior, read by the CLI and the app from one JSON file. Every key
// is optional (defaults below and in the option structs); unknown keys and out-of-range values are
// errors naming the file and the key.
//
// {
//   "odometry": {"features": {...}, "deskew": {"mode": "none"}, "registration": {...}, "local_map": {...}},
//   "keyframes": {"distance": 2.0, "rotation_deg": 10.0},
//   "road_points": {}, "match": {}, "graph": {}
// }
struct Config {
  OdometryOptions odometry;
  KeyframeOptions keyframes;

  // RESERVED for the stages built elsewhere (road points, the 2-D NDT matcher, the pose graph):
  // until their option structs are wired in here, each section must be a JSON object and is kept
  // verbatim (as JSON text) so saving a loaded file does not lose it.
  std::string roadPointsJson = "{}";
  std::string matchJson = "{}";
  std::string graphJson = "{}";
};

Config parseConfig(const std::string& jsonText, const std::string& source);
std::string formatConfig(const Config& config);  // pretty JSON with every key
Config loadConfig(const std::filesystem::path& path);
void saveConfig(const std::filesystem::path& path, const Config& config);

}  // namespace hdprior
