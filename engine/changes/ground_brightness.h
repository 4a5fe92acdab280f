#pragma once
#include <vector>

#include "engine/io/lidar_sweep.h"
#include "engine/lidar/sweep_road_points.h"

namespace hdprior {

// Each ground point's intensity over the lower quartile of its ring's road points (the sweep's, for
// a ring with few): how bright the ground is against the asphalt at that range. Asphalt is the
// darkest surface of a street: on the real sweeps a half-metre cell's mean reads 1.3-1.4 on the
// road and 2.7-3.1 on the ground beside it. 0 for points that are not ground.
// `labelled` is labelSweep of `sweep` (same points, same order).
std::vector<float> groundBrightness(const LidarSweep& sweep, const LabelledSweep& labelled);

}  // namespace hdprior
