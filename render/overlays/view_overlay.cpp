#include "render/overlays/view_overlay.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "render/gpu_mesh.h"
#include "render/layers/layer_drawing.h"
#include "render/overlays/colour_bar.h"
#include "render/overlays/marker_legend.h"
#include "render/overlays/scale_bar.h"

namespace hdprior::render {
namespace {

const Eigen::Vector4f kBackdrop{0.08f, 0.09f, 0.11f, 0.72f};

std::vector<ColourScale> distinctColourScales(const std::vector<std::unique_ptr<Layer>>& layers) {
  std::vector<ColourScale> scales;
  for (const auto& layer : layers)
    if (layer->visible)
      if (auto scale = layer->colourScale(); scale && std::find(scales.begin(), scales.end(), *scale) == scales.end())
        scales.push_back(*scale);
  return scales;
}

std::vector<MarkerKey> visibleMarkerKeys(const std::vector<std::unique_ptr<Layer>>& layers) {
  std::vector<MarkerKey> keys;
  for (const auto& layer : layers)
    if (layer->visible)
      for (MarkerKey& key : layer->markerKeys()) keys.push_back(std::move(key));
  return keys;
}

// Stacks blocks in one corner of the free area, each on its backdrop: from the top down when
// `fromTop`, else from the bottom up; at the left or the right edge.
void stack(ScreenCanvas& canvas, const std::vector<OverlayBlock>& blocks, const Eigen::AlignedBox2f& area, bool fromTop,
           bool atLeft) {
  const float pad = 3 * canvas.unit(), gap = 4 * canvas.unit();
  float y = fromTop ? area.min().y() : area.max().y();
  for (const OverlayBlock& block : blocks) {
    const Eigen::Vector2f outer = block.size + Eigen::Vector2f::Constant(2 * pad);
    const float top = fromTop ? y : y - outer.y();
    const float left = atLeft ? area.min().x() : area.max().x() - outer.x();
    canvas.rect(left, top, left + outer.x(), top + outer.y(), kBackdrop);
    block.draw(canvas, {left + pad, top + pad});
    y = fromTop ? top + outer.y() + gap : top - gap;
  }
}

}  // namespace

ScreenCanvas viewOverlay(const std::vector<std::unique_ptr<Layer>>& layers, const Camera& camera, int width, int height,
                         const ScreenInsets& insets) {
  // One font pixel per whole 360 rows left free: 1280 x 720 snapshots get 2, the app's view between
  // its panels 1, like the panels' own text.
  ScreenCanvas canvas(width, height, int((height - insets.top - insets.bottom) / 360.0f));
  const float margin = 8 * canvas.unit();
  const Eigen::AlignedBox2f area(Eigen::Vector2f(insets.left + margin, insets.top + margin),
                                 Eigen::Vector2f(width - insets.right - margin, height - insets.bottom - margin));
  if (area.isEmpty()) return canvas;

  if (const auto keys = visibleMarkerKeys(layers); !keys.empty())
    stack(canvas, {markerLegend(canvas, keys)}, area, true, true);
  if (const std::optional<double> metresPerPixel = camera.metresPerPixel(height))
    stack(canvas, {scaleBar(canvas, *metresPerPixel, std::min(100.0 * canvas.unit(), area.sizes().x() / 3.0))}, area,
          false, true);
  std::vector<OverlayBlock> bars;
  for (const ColourScale& scale : distinctColourScales(layers)) bars.push_back(colourBar(canvas, scale));
  stack(canvas, bars, area, false, false);
  return canvas;
}

ViewOverlayDrawer::ViewOverlayDrawer() : mesh_(std::make_unique<GpuMesh>()) {}
ViewOverlayDrawer::~ViewOverlayDrawer() = default;

void ViewOverlayDrawer::draw(const ScreenCanvas& canvas, const ShaderLibrary& shaders) {
  if (canvas.triangles().empty()) return;
  mesh_->upload(std::span<const ColoredVertex>(canvas.triangles()));
  drawColored(DrawContext{canvas.projection(), shaders}, *mesh_, Primitive::Triangles);
}

}  // namespace hdprior::render
