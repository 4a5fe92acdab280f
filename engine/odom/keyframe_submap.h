#pragma once
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/io/lidar_sweep.h"
#include "engine/odom/odometry.h"

namespace hdprior {

// The paper's key-frame sub-map: the deskewed sweeps since the previous keyframe, placed with their
// odometry poses in the keyframe's ego frame. `sweepOf(frame)` loads the sweep of an odometry frame.
std::vector<Eigen::Vector3f> keyframeSubmap(const Odometry& odometry, const Keyframe& keyframe,
                                            const std::function<std::shared_ptr<const LidarSweep>(size_t)>& sweepOf);

}  // namespace hdprior
