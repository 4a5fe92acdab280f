#include "engine/changes/sweep_alignment.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/geom/se2.h"
#include "engine/lidar/road_points.h"
#include "engine/map/boundary_distance.h"

namespace hdprior {

bool SweepAlignment::misaligned(const ChangeOptions& o, double driven) const {
  return alignedShifted >= 2 * o.minSamples && alignedShifted >= 2 * std::max(alignedAtPose, 1) && shift.norm() > o.tolerance &&
         shift.norm() <= o.poseErrorPerMetre * driven;
}

SweepAlignment sweepAlignment(const LabelledSweep& sweep, const SE3& cityTEgo, const BoundaryDistance& distance,
                              const ChangeOptions& options) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
  const Eigen::Vector2d t = cityTEgo.translation().head<2>();
  std::vector<Eigen::Vector2d> kerbs;  // city frame, at the pose
  for (size_t i = 0; i < sweep.points.size(); ++i)
    if (sweep.road[i] == kCurbPoint) kerbs.push_back(r * sweep.points[i].head<2>() + t);
  SweepAlignment a;
  a.kerbs = int(kerbs.size());
  const auto aligned = [&](const Eigen::Vector2d& cityShift) {
    int n = 0;
    for (const Eigen::Vector2d& k : kerbs) n += std::abs(distance.cellDistance(k + cityShift)) <= options.cell;
    return n;
  };
  a.alignedAtPose = aligned(Eigen::Vector2d::Zero());
  a.alignedShifted = a.alignedAtPose;
  const int steps = int(std::floor(options.reach / options.cell));
  for (int i = -steps; i <= steps; ++i)
    for (int j = -steps; j <= steps; ++j) {
      const Eigen::Vector2d shift(i * options.cell, j * options.cell);
      const int n = aligned(r * shift);
      if (n > a.alignedShifted || (n == a.alignedShifted && shift.norm() < a.shift.norm())) a.alignedShifted = n, a.shift = shift;
    }
  return a;
}

}  // namespace hdprior
