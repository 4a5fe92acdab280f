#include "render/layers/lane_centerline_layer.h"

#include <vector>

#include "engine/map/hd_map.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void LaneCenterlineLayer::setScene(const Scene& scene) {
  // Lanes first, then intersection lanes: two ranges, each tinted with its own colour.
  std::vector<ColoredVertex> vertices;
  for (const bool intersection : {false, true}) {
    for (const Lane& lane : scene.map->laneGraph().lanes()) {
      if (lane.isIntersection != intersection) continue;
      for (size_t i = 1; i < lane.centerline.size(); ++i) {
        vertices.push_back({scene.local(lane.centerline[i - 1]), Eigen::Vector4f::Ones()});
        vertices.push_back({scene.local(lane.centerline[i]), Eigen::Vector4f::Ones()});
      }
    }
    if (!intersection) laneVertices_ = vertices.size();
  }
  lines_ = std::make_unique<GpuMesh>();
  lines_->upload(std::span<const ColoredVertex>(vertices));
}

void LaneCenterlineLayer::draw(const DrawContext& context) const {
  if (laneVertices_ > 0) drawColored(context, *lines_, Primitive::Lines, 1.0f, false, laneColor_, 0, laneVertices_);
  if (lines_->size() > laneVertices_)
    drawColored(context, *lines_, Primitive::Lines, 1.0f, false, intersectionColor_, laneVertices_,
                lines_->size() - laneVertices_);
}

std::vector<LayerOption> LaneCenterlineLayer::options() {
  return {LayerOption::colorPicker("lanes", &laneColor_), LayerOption::colorPicker("in intersections", &intersectionColor_)};
}

}  // namespace hdprior::render
