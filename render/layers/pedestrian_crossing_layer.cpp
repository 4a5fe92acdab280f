#include "render/layers/pedestrian_crossing_layer.h"

#include <array>
#include <vector>

#include "engine/map/hd_map.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {
namespace {

bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const Eigen::Vector2d u = q - p, v = r - p;
    return u.x() * v.y() - u.y() * v.x();
  };
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

}  // namespace

void PedestrianCrossingLayer::setScene(const Scene& scene) {
  std::vector<ColoredVertex> fill, outline;
  const Eigen::Vector4f white = Eigen::Vector4f::Ones(), faint(1.0f, 1.0f, 1.0f, 0.35f);
  for (const PedestrianCrossing& crossing : scene.map->vectorMap().pedestrianCrossings) {
    if (crossing.edge1.size() < 2 || crossing.edge2.size() < 2) continue;
    std::array<Eigen::Vector3d, 4> q = {crossing.edge1.front(), crossing.edge1.back(), crossing.edge2.back(),
                                        crossing.edge2.front()};
    // The edges may run in opposite directions: order the corners around the quad.
    if (segmentsCross(q[1].head<2>(), q[2].head<2>(), q[3].head<2>(), q[0].head<2>())) std::swap(q[2], q[3]);
    std::array<Eigen::Vector3f, 4> c;
    for (int i = 0; i < 4; ++i) c[i] = scene.local(q[i]);
    for (int i : {0, 1, 2, 0, 2, 3}) fill.push_back({c[i], faint});
    for (int i = 0; i < 4; ++i) {
      outline.push_back({c[i], white});
      outline.push_back({c[(i + 1) % 4], white});
    }
  }
  fill_ = std::make_unique<GpuMesh>();
  fill_->upload(std::span<const ColoredVertex>(fill));
  outline_ = std::make_unique<GpuMesh>();
  outline_->upload(std::span<const ColoredVertex>(outline));
}

void PedestrianCrossingLayer::draw(const DrawContext& context) const {
  drawColored(context, *fill_, Primitive::Triangles, 1.0f, false, color_);
  drawColored(context, *outline_, Primitive::Lines, 1.0f, false, color_);
}

std::vector<LayerOption> PedestrianCrossingLayer::options() { return {LayerOption::colorPicker("colour", &color_)}; }

}  // namespace hdprior::render
