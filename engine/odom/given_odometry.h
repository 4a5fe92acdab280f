#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/geom/pose_trajectory.h"
#include "engine/io/trajectory_file.h"

namespace hdprior {

class ArgoverseLog;

// Where a given trajectory's poses are: `first` (the default): in the system's own frame, whatever
// it is; the pose at the first sweep is mapped onto the first ground-truth pose, as the built-in
// odometry is anchored. `city`: already city_T_ego.
enum class GivenOdometryFrame { First, City };

const char* givenOdometryFrameName(GivenOdometryFrame frame);  // "first", "city"
// "first" or "city"; anything else throws Error(source, ...).
GivenOdometryFrame parseGivenOdometryFrame(const std::string& name, const std::string& source);

// A trajectory from another system (hdprior run --odometry FILE) taken as the odometry: poses of the
// ego vehicle frame.
struct GivenOdometry {
  PoseTrajectory trajectory;  // as read (the file's frame)
  GivenOdometryFrame frame = GivenOdometryFrame::First;
  std::string file;
  TrajectoryFormat format = TrajectoryFormat::Tum;
};

// Reads the file (readTrajectoryFile; KITTI lines without a times file are the sweeps, in order).
GivenOdometry readGivenOdometry(const TrajectoryFileSpec& spec, GivenOdometryFrame frame,
                                const std::vector<int64_t>& sweepTimestampsNs);

// A sweep may lie this far outside the file's time span; it takes the nearest end pose (1 ms: 2 cm at
// 20 m/s, and the rounding of any timestamp written in milliseconds or finer).
constexpr int64_t kGivenOdometryToleranceNs = 1'000'000;

// The given trajectory at every sweep timestamp, interpolated on SE(3) (slerp, linear translation),
// as odom_T_ego of the built-in odometry: odometry frame = the first sweep's ego frame, placed in the
// city by cityTOdom (the first ground-truth pose). `first`: file(t0)^-1 file(t); `city`:
// cityTOdom^-1 file(t), so that cityTOdom * odom_T_ego is the file's pose. Throws Error naming the
// file when the sweeps are not covered (more than the tolerance before its first pose or after its last).
PoseTrajectory givenOdometryAtSweeps(const GivenOdometry& given, const std::vector<int64_t>& sweepTimestampsNs,
                                     const SE3& cityTOdom);

// How to read a trajectory file given as the odometry (run --odometry-format / --odometry-frame /
// --odometry-times, the app's Pipeline tab).
struct OdometryFileOptions {
  std::optional<TrajectoryFormat> format;  // nullopt: detected (trajectory_file.h)
  GivenOdometryFrame frame = GivenOdometryFrame::First;
  std::optional<std::filesystem::path> times;
};

// The trajectory `file` read as the log's odometry.
GivenOdometry givenOdometryOf(const std::filesystem::path& file, const OdometryFileOptions& options, const ArgoverseLog& log);

// The given trajectory at every sweep of the log in the city frame, anchored as a Session anchors it
// (at the ground-truth pose of the first sweep): the odometry trajectory a run over it reports
// (before any injected drift). Throws Error naming the file when it does not cover the sweeps, or
// the log when its poses do not cover the first sweep.
PoseTrajectory givenOdometryInCity(const GivenOdometry& given, const ArgoverseLog& log);

}  // namespace hdprior
