#include "engine/sim/lidar_model.h"

#include <cmath>
#include <numbers>

namespace hdprior {
namespace {

// Elevations (degrees) of a 32-beam automotive lidar in laser order (interleaved low/high).
std::vector<double> elevationTableRadians() {
  const double ascending[32] = {-25.0, -15.64, -11.31, -8.84, -7.25, -6.15, -5.33, -4.67, -4.0,  -3.67, -3.33,
                                -3.0,  -2.67,  -2.33,  -2.0,  -1.67, -1.33, -1.0,  -0.67, -0.33, 0.0,   0.33,
                                0.67,  1.0,    1.33,   1.67,  2.33,  3.33,  4.67,  7.0,   10.33, 15.0};
  std::vector<double> out(32);
  for (int i = 0; i < 32; ++i) {
    // Even lasers take the lower half, odd lasers the upper half: neighbours in laser order
    // are far apart in elevation, as on the real sensors.
    const int k = (i % 2 == 0) ? i / 2 : 16 + i / 2;
    out[size_t(i)] = ascending[k] * std::numbers::pi / 180.0;
  }
  return out;
}

}  // namespace

size_t LidarModel::beamCount() const {
  size_t n = 0;
  for (const LidarUnit& u : units) n += u.elevations.size();
  return n;
}

SensorCalibration LidarModel::calibration() const {
  SensorCalibration out;
  for (const LidarUnit& u : units) out[u.name] = u.egoTSensor;
  return out;
}

LidarModel argoverseLikeLidar() {
  LidarModel m;
  LidarUnit up;
  up.name = "up_lidar";
  up.egoTSensor = makeSE3(Eigen::Quaterniond::Identity(), Eigen::Vector3d(1.35, 0.0, 1.64));
  up.elevations = elevationTableRadians();
  up.firstLaserNumber = 0;
  // Ego-frame azimuths at offset_ns = 0 as measured on real Argoverse 2 sweeps
  // (tests/engine/sim/argoverse_convention_test.cpp): about 140 and -40 degrees.
  up.startAzimuth = 140.0 * std::numbers::pi / 180.0;
  LidarUnit down = up;
  down.name = "down_lidar";
  // Upside down (180 degrees about x), just below the up lidar.
  down.egoTSensor = makeSE3(Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX())),
                            Eigen::Vector3d(1.35, 0.0, 1.52));
  down.firstLaserNumber = 32;
  down.startAzimuth = -40.0 * std::numbers::pi / 180.0;  // half a turn from the up lidar
  m.units = {up, down};
  return m;
}

}  // namespace hdprior
