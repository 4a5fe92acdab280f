#include "render/layers/drivable_boundary_layer.h"

#include <vector>

#include "engine/map/hd_map.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void DrivableBoundaryLayer::setScene(const Scene& scene) {
  const HdMap& map = *scene.map;
  std::vector<ColoredVertex> vertices;
  vertices.reserve(map.drivable().boundaryPoints().size());
  for (const Eigen::Vector2d& p : map.drivable().boundaryPoints()) {
    vertices.push_back({scene.local({p.x(), p.y(), scene.groundZ(p, scene.origin.z())}), {1.0f, 1.0f, 1.0f, 1.0f}});
  }
  points_ = std::make_unique<GpuMesh>();
  points_->upload(std::span<const ColoredVertex>(vertices));
}

void DrivableBoundaryLayer::draw(const DrawContext& context) const {
  drawColored(context, *points_, Primitive::Points, pointSize_, false, color_);
}

std::vector<LayerOption> DrivableBoundaryLayer::options() {
  return {LayerOption::colorPicker("colour", &color_), LayerOption::slider("point size", &pointSize_, 1.0f, 6.0f)};
}

}  // namespace hdprior::render
