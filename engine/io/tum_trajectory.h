#pragma once
#include <filesystem>

#include "engine/geom/pose_trajectory.h"

namespace hdprior {

// TUM trajectory text: one pose per line, `timestamp tx ty tz qx qy qz qw`, timestamp in seconds
// (written with all nine nanosecond digits so it reads back exactly); '#' lines are comments.
std::string formatTum(const PoseTrajectory& trajectory);
PoseTrajectory parseTum(const std::string& text, const std::string& source);
void writeTum(const std::filesystem::path& path, const PoseTrajectory& trajectory);
PoseTrajectory readTum(const std::filesystem::path& path);

}  // namespace hdprior
