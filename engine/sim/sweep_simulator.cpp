#include "engine/sim/sweep_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "engine/sim/ray_caster.h"

namespace hdprior {

SimulatedSweep simulateSweep(const Scene& scene, const LidarModel& lidar, const PoseTrajectory& cityTEgo,
                             int64_t sweepNs, const SweepNoise& noise, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> rangeNoise(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const SE3 egoAtSweepTCity = cityTEgo.at(sweepNs).inverse();
  const SE3 mid = cityTEgo.at(sweepNs + lidar.periodNs / 2);
  const std::vector<SceneBox> moving =
      scene.movingBoxesAt(sweepNs + lidar.periodNs / 2, mid.translation().head<2>(), lidar.maxRange, 10.0);

  // Sensor-frame unit directions per unit, column-independent parts.
  SimulatedSweep out;
  out.sweep.timestampNs = sweepNs;
  out.sweep.points.reserve(lidar.beamCount() * size_t(lidar.azimuthSteps));
  out.labels.reserve(out.sweep.points.capacity());
  for (int c = 0; c < lidar.azimuthSteps; ++c) {
    const int64_t offset = lidar.columnOffsetNs(c);
    const SE3 cityTEgoNow = cityTEgo.at(sweepNs + offset);
    for (const LidarUnit& unit_ : lidar.units) {
      const SE3 cityTSensor = cityTEgoNow * unit_.egoTSensor;
      const Eigen::Vector3d origin = cityTSensor.translation();
      const Eigen::Matrix3d R = cityTSensor.linear();
      // Both units turn clockwise seen from above in the ego frame; an upside-down unit
      // therefore turns the other way in its own frame.
      const double egoAzimuth = unit_.startAzimuth - 2.0 * std::numbers::pi * c / lidar.azimuthSteps;
      const double azimuth = unit_.egoTSensor.linear()(2, 2) < 0.0 ? -egoAzimuth : egoAzimuth;
      const double ca = std::cos(azimuth), sa = std::sin(azimuth);
      for (size_t l = 0; l < unit_.elevations.size(); ++l) {
        const double el = unit_.elevations[l];
        const Eigen::Vector3d dir = R * Eigen::Vector3d(std::cos(el) * ca, std::cos(el) * sa, std::sin(el));
        const auto hit = castRay(scene, moving, origin, dir, lidar.maxRange);
        // Draw the random numbers for every ray, hit or not, so they stay aligned.
        const double drop = unit(rng), n = rangeNoise(rng), speckle = unit(rng);
        if (!hit || drop < noise.dropout || hit->range < lidar.minRange) continue;
        const double range = hit->range + noise.rangeSigma * n;
        const Eigen::Vector3d p = egoAtSweepTCity * (origin + range * dir);
        LidarPoint pt;
        pt.x = float(p.x());
        pt.y = float(p.y());
        pt.z = float(p.z());
        const double intensity = hit->reflectivity * (0.35 + 0.65 * hit->cosIncidence) * (0.8 + 0.4 * speckle);
        pt.intensity = uint8_t(std::clamp(intensity, 0.0, 255.0));
        pt.laserNumber = uint8_t(unit_.firstLaserNumber + int(l));
        pt.offsetNs = int32_t(offset);
        out.sweep.points.push_back(pt);
        out.labels.push_back(uint8_t(hit->label));
      }
    }
  }
  return out;
}

}  // namespace hdprior
