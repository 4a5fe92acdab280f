#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/geom/pose_trajectory.h"

namespace hdprior {

// KITTI odometry poses: one pose per line, the 12 numbers of the 3x4 matrix [R | t] row by row
// (r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz); no timestamps: line i is frame i. Blank lines and
// '#' lines are skipped. The rotation must be within 1e-3 of orthonormal (it is then made so).
std::string formatKitti(const std::vector<SE3>& poses);
// Throws Error("<source>:<line>", reason) for a line without exactly 12 fields, a field that is not a
// number or not finite, or a 3x3 part that is not a rotation.
std::vector<SE3> parseKitti(const std::string& text, const std::string& source);

// A KITTI times file: one timestamp (seconds) per line, strictly increasing. Throws Error naming
// the line otherwise.
std::vector<int64_t> parseTimes(const std::string& text, const std::string& source);
std::string formatTimes(const std::vector<int64_t>& timestampsNs);

// The KITTI poses at these timestamps (the sweeps', or a times file's); throws Error(source) when the
// counts differ, saying what the timestamps are (`timesSource`).
PoseTrajectory kittiTrajectory(std::vector<SE3> poses, std::vector<int64_t> timestampsNs, const std::string& source,
                               const std::string& timesSource);

}  // namespace hdprior
