#include "render/layers/drivable_raster_layer.h"

#include <vector>

#include "engine/map/hd_map.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void DrivableRasterLayer::setScene(const Scene& scene) {
  const DrivableRaster& raster = scene.map->drivable();
  std::vector<uint8_t> mask = raster.cellBytes();
  for (uint8_t& cell : mask) cell = cell ? 255 : 0;
  texture_ = std::make_unique<GpuTexture>();
  texture_->upload(raster.geometry().cols, raster.geometry().rows, mask, TextureFormat::Mask8, false);
  quad_ = std::make_unique<GpuMesh>();
}

void DrivableRasterLayer::setFrame(const Scene& scene, const Frame& frame) {
  // Grid row 0 is the southern-most: texture v = 0 at the grid origin.
  const GridGeometry& g = scene.map->drivable().geometry();
  const double z = frame.groundZ - 0.05;
  const Eigen::Vector2d o = g.origin;
  const auto vertices = texturedQuad({scene.local({o.x(), o.y(), z}), scene.local({o.x() + g.width(), o.y(), z}),
                                      scene.local({o.x() + g.width(), o.y() + g.height(), z}),
                                      scene.local({o.x(), o.y() + g.height(), z})});
  quad_->upload(std::span<const TexturedVertex>(vertices));
}

void DrivableRasterLayer::draw(const DrawContext& context) const { drawTextured(context, *quad_, *texture_, color_); }

std::vector<LayerOption> DrivableRasterLayer::options() { return {LayerOption::colorPicker("colour", &color_)}; }

}  // namespace hdprior::render
