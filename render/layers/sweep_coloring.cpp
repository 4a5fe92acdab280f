#include "render/layers/sweep_coloring.h"

#include <cmath>

#include "engine/io/lidar_sweep.h"
#include "engine/map/hd_map.h"
#include "render/colormap.h"
#include "render/scene.h"

namespace hdprior::render {
namespace {

// Neighbouring laser numbers get far-apart colours, so rings stand out.
float laserShade(uint8_t laser) { return float((laser * 23) % 64) / 63.0f; }

}  // namespace

std::optional<ColourScale> sweepColourScale(SweepColoring coloring) {
  if (coloring == SweepColoring::Height)
    return ColourScale{"lidar: height above ground", kSweepHeightLow, kSweepHeightHigh, "m", false, turbo};
  if (coloring == SweepColoring::Intensity) return ColourScale{"lidar: intensity", 0.0, kSweepIntensityHigh, "", true, turbo};
  return std::nullopt;
}

std::vector<ColoredVertex> sweepVertices(const Scene& scene, const LidarSweep& sweep, const SE3& cityTEgo,
                                         double egoGroundZ, SweepColoring coloring) {
  std::vector<ColoredVertex> vertices;
  vertices.reserve(sweep.points.size());
  // local = city - origin = R p + (t - origin), composed once in double.
  const Eigen::Matrix3f R = cityTEgo.linear().cast<float>();
  const Eigen::Vector3f t = (cityTEgo.translation() - scene.origin).cast<float>();
  const GroundHeight* surface = scene.map->hasGroundHeight() ? &scene.map->groundHeight() : nullptr;
  const float egoGround = float(egoGroundZ - scene.origin.z());
  for (const LidarPoint& p : sweep.points) {
    const Eigen::Vector3f q = R * Eigen::Vector3f(p.x, p.y, p.z) + t;
    float shade = 0.0f;
    if (coloring == SweepColoring::Height) {
      // Height above the ground surface under the point (sloped roads stay one colour).
      const double h = surface ? surface->bilinearAt(scene.origin.head<2>() + q.head<2>().cast<double>()) : NAN;
      const float ground = std::isfinite(h) ? float(h - scene.origin.z()) : egoGround;
      shade = (q.z() - ground - kSweepHeightLow) / (kSweepHeightHigh - kSweepHeightLow);
    } else if (coloring == SweepColoring::Intensity) {
      shade = float(p.intensity) / kSweepIntensityHigh;
    } else {
      shade = laserShade(p.laserNumber);
    }
    const Eigen::Vector3f c = turbo(shade);
    vertices.push_back({q, {c.x(), c.y(), c.z(), 1.0f}});
  }
  return vertices;
}

}  // namespace hdprior::render
