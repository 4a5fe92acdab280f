#include "render/layers/lane_centerline_layer.h"

#include <vector>

#include "engine/map/hd_map.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void LaneCenterlineLayer::setScene(const Scene& scene) {
  std::vector<ColoredVertex> vertices;
  for (const Lane& lane : scene.map->laneGraph().lanes()) {
    const Eigen::Vector4f color = lane.isIntersection ? Eigen::Vector4f(0.85f, 0.85f, 1.0f, 0.45f)
                                                      : Eigen::Vector4f(1.0f, 1.0f, 1.0f, 0.85f);
    for (size_t i = 1; i < lane.centerline.size(); ++i) {
      vertices.push_back({scene.local(lane.centerline[i - 1]), color});
      vertices.push_back({scene.local(lane.centerline[i]), color});
    }
  }
  lines_ = std::make_unique<GpuMesh>();
  lines_->upload(std::span<const ColoredVertex>(vertices));
}

void LaneCenterlineLayer::draw(const DrawContext& context) const {
  drawColored(context, *lines_, Primitive::Lines);
}

}  // namespace hdprior::render
