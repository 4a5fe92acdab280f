#include "engine/eval/trajectory_errors.h"

#include <algorithm>
#include <cmath>

#include "engine/error.h"

namespace hdprior {
namespace {

double angleDeg(const SE3& T) { return Eigen::AngleAxisd(T.rotation()).angle() * 180.0 / M_PI; }
double yawDeg(const SE3& T) { return std::atan2(T.rotation()(1, 0), T.rotation()(0, 0)) * 180.0 / M_PI; }

// |along|, |lateral|: the horizontal offset of est from gt in gt's heading.
Eigen::Vector2d horizontalOffset(const SE3& gt, const SE3& est) {
  const double yaw = std::atan2(gt.rotation()(1, 0), gt.rotation()(0, 0));
  const Eigen::Vector3d d = est.translation() - gt.translation();
  return Eigen::Vector2d(std::cos(yaw) * d.x() + std::sin(yaw) * d.y(), -std::sin(yaw) * d.x() + std::cos(yaw) * d.y()).cwiseAbs();
}

}  // namespace

ErrorStats errorStats(std::vector<double> v) {
  ErrorStats s;
  s.count = v.size();
  if (v.empty()) return s;
  double sum = 0, sq = 0;
  for (double x : v) {
    sum += x;
    sq += x * x;
    s.max = std::max(s.max, x);
  }
  s.mean = sum / double(v.size());
  s.rmse = std::sqrt(sq / double(v.size()));
  s.std = std::sqrt(std::max(0.0, sq / double(v.size()) - s.mean * s.mean));
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  return s;
}

AssociatedPoses associateByTime(const PoseTrajectory& gt, const PoseTrajectory& estimate) {
  AssociatedPoses out;
  size_t outside = 0;
  for (size_t i = 0; i < estimate.size(); ++i) {
    const int64_t t = estimate.timestamps()[i];
    if (!gt.covers(t)) {
      ++outside;
      continue;
    }
    out.timestampsNs.push_back(t);
    out.gt.push_back(gt.at(t));
    out.estimate.push_back(estimate.poses()[i]);
  }
  if (outside > 0 || estimate.empty()) {
    throw Error("evaluation", std::to_string(outside) + " of " + std::to_string(estimate.size()) +
                                  " estimate timestamps fall outside the ground truth's span" +
                                  (gt.empty() ? std::string(" (no ground truth)")
                                              : " [" + std::to_string(gt.startNs()) + ", " + std::to_string(gt.endNs()) + "] ns"));
  }
  return out;
}

AteResult absoluteTrajectoryError(const std::vector<SE3>& gt, const std::vector<SE3>& est) {
  if (gt.size() != est.size()) throw Error("evaluation", "ATE needs matched trajectories");
  AteResult r;
  for (size_t i = 0; i < gt.size(); ++i) {
    const SE3 E = gt[i].inverse() * est[i];
    r.translationErrors.push_back(E.translation().norm());
    r.rotationErrorsDeg.push_back(angleDeg(E));
    const Eigen::Vector2d offset = horizontalOffset(gt[i], est[i]);
    r.alongErrors.push_back(offset.x());
    r.lateralErrors.push_back(offset.y());
  }
  r.translation = errorStats(r.translationErrors);
  r.rotationDeg = errorStats(r.rotationErrorsDeg);
  r.along = errorStats(r.alongErrors);
  r.lateral = errorStats(r.lateralErrors);
  return r;
}

RpeResult relativePoseError(const std::vector<SE3>& gt, const std::vector<SE3>& est, double length) {
  RpeResult r;
  r.length = length;
  std::vector<double> distance(gt.size(), 0.0);
  for (size_t i = 1; i < gt.size(); ++i) distance[i] = distance[i - 1] + (gt[i].translation() - gt[i - 1].translation()).norm();
  double t = 0, yaw = 0, rot = 0;
  size_t j = 0;
  for (size_t i = 0; i < gt.size(); ++i) {
    j = std::max(j, i);
    while (j < gt.size() && distance[j] - distance[i] < length) ++j;
    if (j == gt.size()) break;
    const SE3 E = (gt[i].inverse() * gt[j]).inverse() * (est[i].inverse() * est[j]);
    t += E.translation().norm() / length * 100.0;
    yaw += std::abs(yawDeg(E)) / length * 100.0;
    rot += angleDeg(E) / length * 100.0;
    ++r.segments;
  }
  if (r.segments > 0) {
    r.translationPercent = t / double(r.segments);
    r.yawDegPer100m = yaw / double(r.segments);
    r.rotationDegPer100m = rot / double(r.segments);
  }
  return r;
}

TrajectoryEvaluation evaluateTrajectory(const PoseTrajectory& gtTrajectory, const PoseTrajectory& estimate,
                                        AlignmentMode mode) {
  const AssociatedPoses pairs = associateByTime(gtTrajectory, estimate);
  const Alignment alignment = alignTrajectories(pairs.gt, pairs.estimate, mode);
  const std::vector<SE3> aligned = alignment.apply(pairs.estimate);
  TrajectoryEvaluation e;
  e.mode = mode;
  e.label = alignmentLabel(mode);
  e.scale = alignment.scale;
  for (size_t i = 1; i < pairs.gt.size(); ++i) e.pathLength += (pairs.gt[i].translation() - pairs.gt[i - 1].translation()).norm();
  e.ate = absoluteTrajectoryError(pairs.gt, aligned);
  e.rpe10 = relativePoseError(pairs.gt, aligned, 10.0);
  e.rpe100 = relativePoseError(pairs.gt, aligned, 100.0);
  return e;
}

}  // namespace hdprior
