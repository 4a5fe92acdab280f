#include "render/layers/trajectory_layer.h"

#include <vector>

#include "engine/io/argoverse_log.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void TrajectoryLayer::setScene(const Scene& scene) {
  std::vector<ColoredVertex> vertices;
  for (const SE3& pose : scene.log->cityTEgo().poses())
    vertices.push_back({scene.local(pose.translation()), {0.15f, 0.95f, 0.35f, 1.0f}});
  line_ = std::make_unique<GpuMesh>();
  line_->upload(std::span<const ColoredVertex>(vertices));
}

void TrajectoryLayer::draw(const DrawContext& context) const {
  drawColored(context, *line_, Primitive::LineStrip);
  drawColored(context, *line_, Primitive::Points, 3.0f, true);
}

}  // namespace hdprior::render
