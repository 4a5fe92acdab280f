#pragma once
#include <filesystem>

#include "app/command_line.h"
#include "engine/pipeline/config.h"

namespace hdprior::app {

// --config FILE (the one JSON configuration), or the defaults without it; then
// --odometry-drift SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M] (for commands that accept it) replaces
// the file's odometry.drift.
Config configOption(const CommandLine& cl);

// An output folder: returned as given when it does not exist yet or is a folder; throws otherwise.
std::filesystem::path outputFolder(const std::filesystem::path& out);

}  // namespace hdprior::app
