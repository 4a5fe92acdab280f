#include "engine/odom/keyframe_submap.h"

namespace hdprior {

std::vector<Eigen::Vector3f> keyframeSubmap(const Odometry& odometry, const Keyframe& keyframe,
                                            const std::function<std::shared_ptr<const LidarSweep>(size_t)>& sweepOf) {
  std::vector<Eigen::Vector3f> out;
  const SE3 keyTOdom = keyframe.odomTEgo.inverse();
  for (const size_t frame : keyframe.submapFrames) {
    const auto sweep = sweepOf(frame);
    const Eigen::Isometry3f T = (keyTOdom * odometry.frames().at(frame).odomTEgo).cast<float>();
    for (const auto& p : odometry.deskewed(*sweep, frame)) out.push_back(T * p);
  }
  return out;
}

}  // namespace hdprior
