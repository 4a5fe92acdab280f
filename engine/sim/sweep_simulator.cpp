#include "engine/sim/sweep_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "engine/sim/ray_caster.h"

namespace hdprior {
namespace {

double azimuthOf(const LidarModel& lidar, const LidarUnit& unit, int column) {
  // Both units turn clockwise seen from above in the ego frame; an upside-down unit
  // therefore turns the other way in its own frame.
  const double egoAzimuth = unit.startAzimuth - 2.0 * std::numbers::pi * column / lidar.azimuthSteps;
  return unit.egoTSensor.linear()(2, 2) < 0.0 ? -egoAzimuth : egoAzimuth;
}

void addPoint(const Eigen::Vector3d& egoPoint, const RayHit& hit, double speckle, int laserNumber, int64_t offset,
              SimulatedSweep& out) {
  LidarPoint pt;
  pt.x = float(egoPoint.x());
  pt.y = float(egoPoint.y());
  pt.z = float(egoPoint.z());
  const double intensity = hit.reflectivity * (0.35 + 0.65 * hit.cosIncidence) * (0.8 + 0.4 * speckle);
  pt.intensity = uint8_t(std::clamp(intensity, 0.0, 255.0));
  pt.laserNumber = uint8_t(laserNumber);
  pt.offsetNs = int32_t(offset);
  out.sweep.points.push_back(pt);
  out.labels.push_back(uint8_t(hit.label));
}

// The cosine and sine of each laser's elevation: a ray's direction in its unit's frame is
// (cos el cos az, cos el sin az, sin el), and the elevations are the same every column.
struct ElevationTrig {
  std::vector<double> cos, sin;
};

ElevationTrig elevationTrig(const LidarUnit& unit, bool withErrors) {
  ElevationTrig t;
  for (size_t l = 0; l < unit.elevations.size(); ++l) {
    const double error = withErrors && l < unit.elevationErrors.size() ? unit.elevationErrors[l] : 0.0;
    t.cos.push_back(std::cos(unit.elevations[l] + error));
    t.sin.push_back(std::sin(unit.elevations[l] + error));
  }
  return t;
}

// One column of a sensor that is not what it believes: the rays leave from its true mounting
// at its true elevations and ranges are biased, but the points are placed the way the sensor
// would place them: the measured range along the believed beam, through the believed
// calibration (what Argoverse 2 stores).
void castImperfectColumn(const Scene& scene, std::span<const SceneBox> moving, const LidarModel& lidar,
                         const LidarUnit& unit, int column, const SE3& cityTEgoNow, const SE3& egoAtSweepTCity,
                         const ElevationTrig& believed, const ElevationTrig& real, const SweepNoise& noise,
                         std::mt19937_64& rng, std::normal_distribution<double>& rangeNoise,
                         std::uniform_real_distribution<double>& uniform, SimulatedSweep& out) {
  const SE3 cityTTrue = cityTEgoNow * unit.trueEgoTSensor.value_or(unit.egoTSensor);
  const SE3 egoAtSweepTBelieved = egoAtSweepTCity * cityTEgoNow * unit.egoTSensor;
  const double azimuth = azimuthOf(lidar, unit, column);
  const double ca = std::cos(azimuth), sa = std::sin(azimuth);
  const int64_t offset = lidar.columnOffsetNs(column);
  for (size_t l = 0; l < unit.elevations.size(); ++l) {
    const Eigen::Vector3d trueDir = cityTTrue.linear() * Eigen::Vector3d(real.cos[l] * ca, real.cos[l] * sa, real.sin[l]);
    const auto hit = castRay(scene, moving, cityTTrue.translation(), trueDir, lidar.maxRange);
    const double drop = uniform(rng), n = rangeNoise(rng), speckle = uniform(rng);
    if (!hit || drop < noise.dropout || hit->range < lidar.minRange) continue;
    const double bias = l < unit.rangeBiases.size() ? unit.rangeBiases[l] : 0.0;
    const double range = hit->range + bias + noise.rangeSigma * n;
    const Eigen::Vector3d beam(believed.cos[l] * ca, believed.cos[l] * sa, believed.sin[l]);
    addPoint(egoAtSweepTBelieved * (range * beam), *hit, speckle, unit.firstLaserNumber + int(l), offset, out);
  }
}

}  // namespace

SimulatedSweep simulateSweep(const Scene& scene, const LidarModel& lidar, const PoseTrajectory& cityTEgo,
                             int64_t sweepNs, const SweepNoise& noise, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> rangeNoise(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const SE3 egoAtSweepTCity = cityTEgo.at(sweepNs).inverse();
  const SE3 mid = cityTEgo.at(sweepNs + lidar.periodNs / 2);
  const std::vector<SceneBox> moving =
      scene.movingBoxesAt(sweepNs + lidar.periodNs / 2, mid.translation().head<2>(), lidar.maxRange, 10.0);

  std::vector<ElevationTrig> believed, real;
  for (const LidarUnit& u : lidar.units) {
    believed.push_back(elevationTrig(u, false));
    real.push_back(elevationTrig(u, true));
  }
  SimulatedSweep out;
  out.sweep.timestampNs = sweepNs;
  out.sweep.points.reserve(lidar.beamCount() * size_t(lidar.azimuthSteps));
  out.labels.reserve(out.sweep.points.capacity());
  for (int c = 0; c < lidar.azimuthSteps; ++c) {
    const int64_t offset = lidar.columnOffsetNs(c);
    const SE3 cityTEgoNow = cityTEgo.at(sweepNs + offset);
    for (size_t u = 0; u < lidar.units.size(); ++u) {
      const LidarUnit& unit_ = lidar.units[u];
      if (!unit_.ideal()) {
        castImperfectColumn(scene, moving, lidar, unit_, c, cityTEgoNow, egoAtSweepTCity, believed[u], real[u], noise, rng,
                            rangeNoise, unit, out);
        continue;
      }
      const SE3 cityTSensor = cityTEgoNow * unit_.egoTSensor;
      const Eigen::Vector3d origin = cityTSensor.translation();
      const Eigen::Matrix3d R = cityTSensor.linear();
      const double azimuth = azimuthOf(lidar, unit_, c);
      const double ca = std::cos(azimuth), sa = std::sin(azimuth);
      for (size_t l = 0; l < unit_.elevations.size(); ++l) {
        const Eigen::Vector3d dir = R * Eigen::Vector3d(believed[u].cos[l] * ca, believed[u].cos[l] * sa, believed[u].sin[l]);
        const auto hit = castRay(scene, moving, origin, dir, lidar.maxRange);
        // Draw the random numbers for every ray, hit or not, so they stay aligned.
        const double drop = unit(rng), n = rangeNoise(rng), speckle = unit(rng);
        if (!hit || drop < noise.dropout || hit->range < lidar.minRange) continue;
        const double range = hit->range + noise.rangeSigma * n;
        addPoint(egoAtSweepTCity * (origin + range * dir), *hit, speckle, unit_.firstLaserNumber + int(l), offset, out);
      }
    }
  }
  return out;
}

}  // namespace hdprior
