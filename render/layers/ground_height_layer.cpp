#include "render/layers/ground_height_layer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/map/hd_map.h"
#include "render/colormap.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

std::optional<HeightRange> groundHeightColorRange(const GroundHeight& g) {
  std::vector<float> valid;
  for (float h : g.heights())
    if (std::isfinite(h)) valid.push_back(h);
  if (valid.empty()) return std::nullopt;
  std::sort(valid.begin(), valid.end());
  const float lo = valid[valid.size() * 2 / 100], hi = std::max(valid[valid.size() * 98 / 100], lo + 0.1f);
  return HeightRange{lo, hi};
}

void GroundHeightLayer::setScene(const Scene& scene) {
  if (!scene.map->hasGroundHeight()) return;
  const GroundHeight& g = scene.map->groundHeight();
  range_ = groundHeightColorRange(g);
  if (!range_) return;
  const float lo = range_->low, hi = range_->high;

  std::vector<uint8_t> rgba(g.heights().size() * 4, 0);
  for (size_t i = 0; i < g.heights().size(); ++i) {
    const float h = g.heights()[i];
    if (!std::isfinite(h)) continue;
    const Eigen::Vector3f c = terrain((h - lo) / (hi - lo)) * 255.0f;
    rgba[i * 4 + 0] = uint8_t(c.x());
    rgba[i * 4 + 1] = uint8_t(c.y());
    rgba[i * 4 + 2] = uint8_t(c.z());
    rgba[i * 4 + 3] = 255;
  }
  texture_ = std::make_unique<GpuTexture>();
  texture_->upload(g.cols(), g.rows(), rgba, TextureFormat::Rgba8, true);
  // Texture row 0 is image row 0: uv (u/cols, v/rows) is image coordinate (u, v).
  const Sim2& sim2 = g.imgSim2City();
  corners_ = {sim2.imageToCity({0, 0}), sim2.imageToCity({g.cols(), 0}), sim2.imageToCity({g.cols(), g.rows()}),
              sim2.imageToCity({0, g.rows()})};
  quad_ = std::make_unique<GpuMesh>();
}

void GroundHeightLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!quad_) return;
  std::array<Eigen::Vector3f, 4> c;
  for (int i = 0; i < 4; ++i) c[i] = scene.local({corners_[i].x(), corners_[i].y(), frame.groundZ - 0.10});
  const auto vertices = texturedQuad(c);
  quad_->upload(std::span<const TexturedVertex>(vertices));
}

std::optional<ColourScale> GroundHeightLayer::colourScale() const {
  if (!range_) return std::nullopt;
  return ColourScale{"ground height (city z)", range_->low, range_->high, "m", false, terrain};
}

void GroundHeightLayer::draw(const DrawContext& context) const {
  if (quad_) drawTextured(context, *quad_, *texture_, {1.0f, 1.0f, 1.0f, 0.85f});
}

}  // namespace hdprior::render
