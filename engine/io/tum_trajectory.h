#pragma once
#include <filesystem>

#include "engine/geom/pose_trajectory.h"

namespace hdprior {

// TUM trajectory text: one pose per line, `timestamp tx ty tz qx qy qz qw`, timestamp in seconds
// (written with all nine nanosecond digits so it reads back exactly; read exactly in any decimal
// or exponent notation); '#' lines and blank lines are skipped.
// parseTum throws Error("<source>:<line>", reason) for a line without exactly 8 fields, a field that
// is not a number or not finite, a quaternion whose norm is more than 1e-3 from 1 (nearer ones are
// normalised), or a timestamp not after the previous line's.
std::string formatTum(const PoseTrajectory& trajectory);
PoseTrajectory parseTum(const std::string& text, const std::string& source);
void writeTum(const std::filesystem::path& path, const PoseTrajectory& trajectory);
PoseTrajectory readTum(const std::filesystem::path& path);

}  // namespace hdprior
