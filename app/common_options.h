#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "engine/io/argoverse_log.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace hdprior::app {

// LOG, the required positional argument: an Argoverse 2 log's folder.
void addLogArgument(CLI::App& command, std::string& log);

// --config FILE (the one JSON configuration) and, for commands that add it, --odometry-drift
// SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M], which replaces the file's odometry.drift.
struct ConfigArguments {
  std::string file;
  std::string odometryDrift;
};
void addConfigOption(CLI::App& command, ConfigArguments& arguments);
void addOdometryDriftOption(CLI::App& command, ConfigArguments& arguments);
// The file's configuration (the defaults without one) with the drift option applied.
Config configOf(const ConfigArguments& arguments);

// An output folder: returned as given when it does not exist yet or is a folder; throws otherwise.
std::filesystem::path outputFolder(const std::filesystem::path& out);
// An output file (a PNG): throws, naming it, when its folder does not exist or it is a folder.
void checkOutputFile(const std::filesystem::path& out);

// How to read a trajectory file given as the odometry: --odometry-format tum|kitti (default: detected,
// trajectory_file.h), --odometry-frame first|city (default first) and, for commands that add it,
// --odometry-times FILE. Each needs the option `source` (--odometry, --odometry-dir).
struct OdometryFileArguments {
  std::string format, frame = "first", times;
};
void addOdometryFileOptions(CLI::App& command, OdometryFileArguments& arguments, CLI::Option* source);
void addOdometryTimesOption(CLI::App& command, OdometryFileArguments& arguments, CLI::Option* source);
// --odometry FILE (a trajectory file as the odometry) with the three above.
void addGivenOdometryOptions(CLI::App& command, std::string& file, OdometryFileArguments& arguments, const std::string& help);
OdometryFileOptions odometryFileOptions(const OdometryFileArguments& arguments);

}  // namespace hdprior::app
