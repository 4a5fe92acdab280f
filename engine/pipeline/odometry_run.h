#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/eval/trajectory_errors.h"
#include "engine/geom/pose_trajectory.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "engine/pipeline/config.h"

namespace hdprior {

// Lidar odometry over a whole log (no HD-map priors), anchored at the first ground-truth pose.
struct OdometryRun {
  std::unique_ptr<Odometry> odometry;
  SE3 cityTOdom = SE3::Identity();       // the first ground-truth pose
  PoseTrajectory estimate, groundTruth;  // city_T_ego at the sweep timestamps
  std::vector<Eigen::Vector3f> mapPoints;  // voxelised map of the keyframes' sweeps, city frame
  std::vector<float> mapIntensity;
  double wallSeconds = 0;
  size_t maxLocalMapPoints = 0;
};

// progress(done, total) is called after each sweep. Throws Error naming the sweep file for a bad or
// empty sweep, or the log when it has no sweeps or its poses do not cover the first sweep.
OdometryRun runOdometry(const ArgoverseLog& log, const Config& config,
                        const std::function<void(size_t, size_t)>& progress = {}, double mapVoxel = 0.2);

// The metrics of a run: the default evaluation (anchored at the first pose) and, when there are at
// least 3 poses, the labelled SE(3), Sim(3) and 4-DOF alignments.
struct RunMetrics {
  TrajectoryEvaluation anchored;
  std::vector<TrajectoryEvaluation> aligned;
};
RunMetrics evaluateRun(const OdometryRun& run);

// DIR/groundtruth.tum, odometry.tum, keyframes.json, metrics.json, map.ply, each written atomically.
void writeRunOutputs(const std::filesystem::path& dir, const ArgoverseLog& log, const OdometryRun& run,
                     const RunMetrics& metrics);

}  // namespace hdprior
