#include "render/layers/lidar_sweep_layer.h"

#include <vector>

#include "engine/io/lidar_sweep.h"
#include "render/layers/layer_drawing.h"
#include "render/layers/sweep_coloring.h"
#include "render/scene.h"

namespace hdprior::render {

void LidarSweepLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!points_) points_ = std::make_unique<GpuMesh>();
  std::vector<ColoredVertex> vertices;
  if (frame.sweep)
    vertices = sweepVertices(scene, *frame.sweep, frame.cityTEgo, frame.groundZ, SweepColoring(coloring_));
  points_->upload(std::span<const ColoredVertex>(vertices));
}

void LidarSweepLayer::draw(const DrawContext& context) const {
  if (points_) drawLidarPoints(context, *points_, pointSize_);
}

std::optional<ColourScale> LidarSweepLayer::colourScale() const { return sweepColourScale(SweepColoring(coloring_)); }

std::vector<LayerOption> LidarSweepLayer::options() {
  return {LayerOption::choice("colour by", &coloring_, sweepColoringNames(), true),
          LayerOption::slider("point size", &pointSize_, 1.0f, 6.0f)};
}

}  // namespace hdprior::render
