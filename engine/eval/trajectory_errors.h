#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/eval/trajectory_alignment.h"
#include "engine/geom/pose_trajectory.h"

namespace hdprior {

struct ErrorStats {
  size_t count = 0;
  double mean = 0, median = 0, rmse = 0, std = 0, max = 0;
};
ErrorStats errorStats(std::vector<double> values);

// Associated pose pairs: the ground truth interpolated at each estimate timestamp. Throws Error
// saying how many estimate timestamps fall outside the ground truth's span.
struct AssociatedPoses {
  std::vector<int64_t> timestampsNs;
  std::vector<SE3> gt, estimate;
};
AssociatedPoses associateByTime(const PoseTrajectory& gt, const PoseTrajectory& estimate);

// Absolute trajectory error as in the paper: E_i = Q_i^-1 P_i, translation error |t(E_i)| (metres)
// and rotation angle of E_i (degrees) per frame, after the alignment. The along and lateral errors
// are the horizontal offset of P_i from Q_i along and across Q_i's heading (yaw), so roll and
// altitude do not enter: the drivable area sees the lateral part, and along the road only where
// its shape changes (junctions, curves).
struct AteResult {
  std::vector<double> translationErrors, rotationErrorsDeg, alongErrors, lateralErrors;
  ErrorStats translation, rotationDeg, along, lateral;
};
AteResult absoluteTrajectoryError(const std::vector<SE3>& gt, const std::vector<SE3>& alignedEstimate);

// KITTI-style relative pose error over segments of `length` metres of ground-truth path, from every
// frame: E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j). Drift is |t(E)| / length in %, yaw drift |yaw(E)| in
// degrees per 100 m, rotation drift angle(E) in degrees per 100 m; means over segments.
struct RpeResult {
  double length = 0;
  size_t segments = 0;
  double translationPercent = 0, yawDegPer100m = 0, rotationDegPer100m = 0;
};
RpeResult relativePoseError(const std::vector<SE3>& gt, const std::vector<SE3>& estimate, double length);

struct TrajectoryEvaluation {
  AlignmentMode mode = AlignmentMode::None;
  std::string label;
  double scale = 1.0;
  double pathLength = 0;  // metres of ground truth
  AteResult ate;
  RpeResult rpe10, rpe100;
};
TrajectoryEvaluation evaluateTrajectory(const PoseTrajectory& gt, const PoseTrajectory& estimate, AlignmentMode mode);

}  // namespace hdprior
