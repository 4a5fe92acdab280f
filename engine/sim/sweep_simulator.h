#pragma once
#include <cstdint>
#include <vector>

#include "engine/geom/pose_trajectory.h"
#include "engine/io/lidar_sweep.h"
#include "engine/sim/lidar_model.h"
#include "engine/sim/scene.h"

namespace hdprior {

struct SweepNoise {
  double rangeSigma = 0.02;   // metres, Gaussian
  double dropout = 0.02;      // probability that a return is lost
};

struct SimulatedSweep {
  LidarSweep sweep;
  std::vector<uint8_t> labels;  // PointLabel per point
};

// One sweep starting at sweepNs: every column fires from the sensor pose at its own time
// (city_T_ego interpolated at sweepNs + offset), and every return is stored the way
// Argoverse 2 stores it: in the ego frame at the sweep timestamp (motion-compensated),
// offset_ns = firing time - sweepNs in [0, period). Deterministic in `seed`.
SimulatedSweep simulateSweep(const Scene& scene, const LidarModel& lidar, const PoseTrajectory& cityTEgo,
                             int64_t sweepNs, const SweepNoise& noise, uint64_t seed);

}  // namespace hdprior
