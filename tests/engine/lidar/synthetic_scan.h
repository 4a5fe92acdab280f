// A synthetic street scanned by a 32-ring lidar: a 10 m wide road at z = -0.32 (ego frame)
// with 0.15 m curbs, 3 m sidewalks, building walls, and an optional box (a car) on the road.
#pragma once
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>

namespace hdprior::test {

enum class Surface : uint8_t { Road, Curb, Sidewalk, Wall, Car };

struct ScanPoint {
  Eigen::Vector3d p;
  uint8_t ring;
  Surface surface;
};

struct Street {
  double roadZ = -0.32, curb = 0.15, halfWidth = 5.0, sidewalk = 3.0, sensorZ = 1.6;
  bool car = true;  // a 4.5 x 1.8 x 1.5 m box 8 m ahead in the right lane
  double carNearY = -1.0, carClearance = 0.2;  // its side facing the sensor; its floor above the road
  // A kerb across the road this far ahead with raised ground (sidewalk) beyond: the far side of a
  // T-junction the vehicle drives towards.
  double endAt = std::numeric_limits<double>::infinity();
};

inline std::vector<ScanPoint> scanStreet(const Street& s, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<ScanPoint> out;
  const Eigen::Vector3d origin(0, 0, s.sensorZ);
  const double inf = std::numeric_limits<double>::infinity();
  for (int ring = 0; ring < 32; ++ring) {
    const double elevation = (-25.0 + 40.0 * ring / 31.0) * std::numbers::pi / 180.0;
    for (int k = 0; k < 1800; ++k) {
      const double az = k * 2.0 * std::numbers::pi / 1800.0;
      const Eigen::Vector3d d(std::cos(elevation) * std::cos(az), std::cos(elevation) * std::sin(az), std::sin(elevation));
      double best = inf;
      Surface what = Surface::Road;
      const auto consider = [&](double t, Surface surface, auto inside) {
        if (t > 0.1 && t < best && t < 80.0 && inside(origin + t * d)) {
          best = t;
          what = surface;
        }
      };
      if (d.z() < 0) {
        consider((s.roadZ - s.sensorZ) / d.z(), Surface::Road,
                 [&](const Eigen::Vector3d& p) { return std::abs(p.y()) <= s.halfWidth && p.x() <= s.endAt; });
        consider((s.roadZ + s.curb - s.sensorZ) / d.z(), Surface::Sidewalk, [&](const Eigen::Vector3d& p) {
          return std::abs(p.y()) < s.halfWidth + s.sidewalk && (std::abs(p.y()) > s.halfWidth || p.x() > s.endAt);
        });
      }
      if (std::isfinite(s.endAt) && d.x() > 1e-9) {
        consider(s.endAt / d.x(), Surface::Curb, [&](const Eigen::Vector3d& p) {
          return std::abs(p.y()) <= s.halfWidth && p.z() >= s.roadZ && p.z() <= s.roadZ + s.curb;
        });
      }
      for (double side : {-1.0, 1.0}) {
        if (std::abs(d.y()) < 1e-9) continue;
        consider(side * s.halfWidth / d.y(), Surface::Curb,
                 [&](const Eigen::Vector3d& p) { return p.z() >= s.roadZ && p.z() <= s.roadZ + s.curb; });
        consider(side * (s.halfWidth + s.sidewalk) / d.y(), Surface::Wall,
                 [&](const Eigen::Vector3d& p) { return p.z() >= s.roadZ + s.curb && p.z() <= 6.0; });
      }
      if (s.car) {  // the box's faces facing the sensor: x = 6 (rear) and y = -1 (left side)
        if (std::abs(d.x()) > 1e-9) {
          consider(6.0 / d.x(), Surface::Car, [&](const Eigen::Vector3d& p) {
            return p.y() <= s.carNearY && p.y() >= s.carNearY - 1.8 && p.z() >= s.roadZ + s.carClearance && p.z() <= s.roadZ + 1.5;
          });
        }
        if (std::abs(d.y()) > 1e-9) {
          consider(s.carNearY / d.y(), Surface::Car, [&](const Eigen::Vector3d& p) {
            return p.x() >= 6.0 && p.x() <= 10.5 && p.z() >= s.roadZ + s.carClearance && p.z() <= s.roadZ + 1.5;
          });
        }
      }
      if (best == inf) continue;
      Eigen::Vector3d p = origin + best * d;
      p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      out.push_back({p, uint8_t(ring), what});
    }
  }
  return out;
}

}  // namespace hdprior::test
