#include "render/layers/lidar_sweep_layer.h"

#include <cmath>
#include <vector>

#include "engine/io/lidar_sweep.h"
#include "engine/map/hd_map.h"
#include "render/colormap.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void LidarSweepLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!points_) points_ = std::make_unique<GpuMesh>();
  std::vector<ColoredVertex> vertices;
  if (frame.sweep) {
    vertices.reserve(frame.sweep->points.size());
    // local = city - origin = R p + (t - origin), composed once in double.
    const Eigen::Matrix3f R = frame.cityTEgo.linear().cast<float>();
    const Eigen::Vector3f t = (frame.cityTEgo.translation() - scene.origin).cast<float>();
    const GroundHeight* surface = scene.map->hasGroundHeight() ? &scene.map->groundHeight() : nullptr;
    const float egoGround = float(frame.groundZ - scene.origin.z());
    constexpr float kLow = -0.5f, kHigh = 4.0f;  // metres above the ground, the colour range
    for (const LidarPoint& p : frame.sweep->points) {
      const Eigen::Vector3f q = R * Eigen::Vector3f(p.x, p.y, p.z) + t;
      // Height above the ground surface under the point (sloped roads stay one colour).
      const double h = surface ? surface->bilinearAt(scene.origin.head<2>() + q.head<2>().cast<double>()) : NAN;
      const float ground = std::isfinite(h) ? float(h - scene.origin.z()) : egoGround;
      const Eigen::Vector3f c = turbo((q.z() - ground - kLow) / (kHigh - kLow));
      vertices.push_back({q, {c.x(), c.y(), c.z(), 1.0f}});
    }
  }
  points_->upload(std::span<const ColoredVertex>(vertices));
}

void LidarSweepLayer::draw(const DrawContext& context) const {
  if (points_) drawColored(context, *points_, Primitive::Points, 2.0f);
}

}  // namespace hdprior::render
