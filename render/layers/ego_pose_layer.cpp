#include "render/layers/ego_pose_layer.h"

#include <vector>

#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void EgoPoseLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!triangles_) triangles_ = std::make_unique<GpuMesh>();
  // Ego frame: origin at the rear axle, x forward. A 4.9 m x 2.0 m footprint, 0.3 m up.
  const auto at = [&](double x, double y) { return scene.local(frame.cityTEgo * Eigen::Vector3d(x, y, 0.3)); };
  const Eigen::Vector4f body(1.0f, 1.0f, 1.0f, 1.0f), arrow(1.0f, 1.0f, 1.0f, 1.0f);  // tinted in draw
  const std::vector<ColoredVertex> vertices = {
      {at(-1.0, -1.0), body}, {at(3.9, -1.0), body}, {at(3.9, 1.0), body},
      {at(-1.0, -1.0), body}, {at(3.9, 1.0), body},  {at(-1.0, 1.0), body},
      {at(0.4, -0.7), arrow}, {at(3.6, 0.0), arrow}, {at(0.4, 0.7), arrow},
  };
  triangles_->upload(std::span<const ColoredVertex>(vertices));
}

void EgoPoseLayer::draw(const DrawContext& context) const {
  if (!triangles_) return;
  drawColored(context, *triangles_, Primitive::Triangles, 1.0f, false, bodyColor_, 0, 6);
  drawColored(context, *triangles_, Primitive::Triangles, 1.0f, false, Eigen::Vector4f::Ones(), 6, 3);
}

std::vector<LayerOption> EgoPoseLayer::options() { return {LayerOption::colorPicker("colour", &bodyColor_)}; }

}  // namespace hdprior::render
