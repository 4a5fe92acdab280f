#include "render/layers/ndt_cells_layer.h"

#include <algorithm>
#include <vector>

#include "engine/map/hd_map.h"
#include "engine/map/ndt_grid.h"
#include "render/layers/analysis_drawing.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void NdtCellsLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!lines_) lines_ = std::make_unique<GpuMesh>();
  std::vector<ColoredVertex> vertices;
  const std::vector<NdtGrid>& grids = scene.map->ndtGrids();  // coarse to fine
  if (!grids.empty()) {
    const NdtGrid& grid = grids[grids.size() - 1 - size_t(std::clamp(grid_, 0, int(grids.size()) - 1))];
    const Eigen::Vector2d ego = frame.cityTEgo.translation().head<2>();
    for (const NdtCell& cell : grid.cells()) {
      if ((cell.mean - ego).norm() > radius_) continue;
      const double z = scene.groundZ(cell.mean, frame.groundZ) + 0.03;
      appendLoopLines(vertices, ellipseLoop(scene.local({cell.mean.x(), cell.mean.y(), z}), twoSigmaAxes(cell.covariance), 24),
                      Eigen::Vector4f::Ones());
    }
  }
  lines_->upload(std::span<const ColoredVertex>(vertices));
}

void NdtCellsLayer::draw(const DrawContext& context) const {
  if (lines_ && lines_->size() > 0) drawColored(context, *lines_, Primitive::Lines, 1.0f, false, color_);
}

std::vector<LayerOption> NdtCellsLayer::options() {
  LayerOption radius = LayerOption::slider("radius (m)", &radius_, 10.0f, 100.0f);
  radius.rebuilds = true;
  return {LayerOption::choice("grid", &grid_, {"finest", "second finest", "third finest"}, true), radius,
          LayerOption::colorPicker("colour", &color_)};
}

}  // namespace hdprior::render
