#include "render/layers/trajectory_layer.h"

#include <vector>

#include "engine/io/argoverse_log.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void TrajectoryLayer::setScene(const Scene& scene) {
  std::vector<ColoredVertex> vertices;
  for (const SE3& pose : scene.log->cityTEgo().poses())
    vertices.push_back({scene.local(pose.translation()), {1.0f, 1.0f, 1.0f, 1.0f}});
  line_ = std::make_unique<GpuMesh>();
  line_->upload(std::span<const ColoredVertex>(vertices));
}

void TrajectoryLayer::draw(const DrawContext& context) const {
  drawColored(context, *line_, Primitive::LineStrip, 1.0f, false, color_);
  drawColored(context, *line_, Primitive::Points, 3.0f, true, color_);
}

std::vector<LayerOption> TrajectoryLayer::options() { return {LayerOption::colorPicker("colour", &color_)}; }

}  // namespace hdprior::render
