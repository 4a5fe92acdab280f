#pragma once
#include <filesystem>
#include <optional>

#include "app/command_line.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"

namespace hdprior::app {

// --config FILE (the one JSON configuration), or the defaults without it; then
// --odometry-drift SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M] (for commands that accept it) replaces
// the file's odometry.drift.
Config configOption(const CommandLine& cl);

// An output folder: returned as given when it does not exist yet or is a folder; throws otherwise.
std::filesystem::path outputFolder(const std::filesystem::path& out);

// How to read a trajectory file given as the odometry: --odometry-format tum|kitti (default: detected,
// trajectory_file.h), --odometry-frame first|city (default first) and, for commands that accept
// it, --odometry-times FILE. Throws Error naming the option for an unknown value, or when they come
// without `sourceOption` (--odometry, --odometry-dir).
OdometryFileOptions odometryFileOptions(const CommandLine& cl, const std::string& sourceOption);

}  // namespace hdprior::app
