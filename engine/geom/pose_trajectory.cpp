#include "engine/geom/pose_trajectory.h"

#include <algorithm>

#include "engine/error.h"

namespace hdprior {

PoseTrajectory::PoseTrajectory(std::vector<int64_t> timestampsNs, std::vector<SE3> poses, std::string source)
    : timestamps_(std::move(timestampsNs)), poses_(std::move(poses)), source_(std::move(source)) {
  if (timestamps_.size() != poses_.size()) {
    throw Error(source_, std::to_string(timestamps_.size()) + " timestamps but " + std::to_string(poses_.size()) +
                             " poses");
  }
  for (size_t i = 1; i < timestamps_.size(); ++i) {
    if (timestamps_[i] <= timestamps_[i - 1]) {
      throw Error(source_, "timestamps do not increase at row " + std::to_string(i) + " (" +
                               std::to_string(timestamps_[i - 1]) + " then " + std::to_string(timestamps_[i]) + ")");
    }
  }
}

SE3 PoseTrajectory::at(int64_t tNs) const {
  if (!covers(tNs)) {
    const std::string span = empty() ? std::string("no poses")
                                     : "[" + std::to_string(startNs()) + ", " + std::to_string(endNs()) + "]";
    throw Error(source_, "timestamp " + std::to_string(tNs) + " ns is outside the pose time span " + span);
  }
  const auto it = std::lower_bound(timestamps_.begin(), timestamps_.end(), tNs);
  const size_t i = static_cast<size_t>(it - timestamps_.begin());
  if (*it == tNs) return poses_[i];
  const double s = double(tNs - timestamps_[i - 1]) / double(timestamps_[i] - timestamps_[i - 1]);
  return interpolate(poses_[i - 1], poses_[i], s);
}

}  // namespace hdprior
