#pragma once
#include <filesystem>
#include <string>

#include "engine/graph/pose_graph.h"
#include "engine/graph/pose_prior.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/match/match_options.h"
#include "engine/odom/odometry_options.h"

namespace hdprior {

// The one configuration of hdprior, read by the CLI and the app from one JSON file. Every key is
// optional: a file's keys are set over the defaults. Each key is declared once, next to the options
// struct that holds it (optionFields: its member, whose initialiser is the default, its range, unit
// and description); the schema in config.cpp gathers them into sections. The loader, `config
// --check`, `config --defaults`, the reference (docs/config.md) and the stages' constructors all
// check against those declarations. Unknown keys, wrong types and values out of range are errors
// naming the file and the key.
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

const Config& defaultConfig();

// Throws Error("configuration", "match.min_points = 0 is out of range [1, 10000000]") for a value the
// schema refuses: the check of a configuration made in code rather than read from a file.
void checkConfig(const Config& config);

// The ego origin's height above the road, which the priors' altitude and the road-point extraction
// (as the road level, -egoHeight) both use: one key, vehicle.ego_height.
void setEgoHeight(Config& config, double egoHeight);

Config parseConfig(const std::string& jsonText, const std::string& source);  // its keys over defaultConfig()
std::string formatConfig(const Config& config);  // pretty JSON with every key
Config loadConfig(const std::filesystem::path& path);
void saveConfig(const std::filesystem::path& path, const Config& config);

}  // namespace hdprior
