#include "render/layers/landscape_layer.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/analysis.h"
#include "render/colormap.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void LandscapeLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  analysis_ = &analysis;
  build(scene);
}

void LandscapeLayer::build(const Scene& scene) {
  empty_ = !analysis_ || !analysis_->landscape || analysis_->landscape->size == 0;
  if (empty_) return;
  const Analysis& analysis = *analysis_;
  const CostLandscape& l = *analysis.landscape;
  const auto [lo, hi] = std::minmax_element(l.scores.begin(), l.scores.end());
  low_ = *lo;
  high_ = *hi;
  const double range = std::max(*hi - *lo, 1e-12);
  std::vector<uint8_t> texels;
  texels.reserve(l.scores.size() * 4);
  for (double s : l.scores) {  // row 0 is the southern-most: v = 0
    const Eigen::Vector3f c = turbo(float((s - *lo) / range));
    for (int i = 0; i < 3; ++i) texels.push_back(uint8_t(std::lround(255.0f * c[i])));
    texels.push_back(255);
  }
  texture_ = std::make_unique<GpuTexture>();
  texture_->upload(l.size, l.size, texels, TextureFormat::Rgba8, smooth_ != 0);
  // Cell centres at the offsets: the quad reaches half a step beyond the outer ones.
  const double half = l.offset(l.size - 1) + 0.5 * l.options.step;
  const double fallback = analysis.inspection ? analysis.inspection->keyframePose.translation().z() : scene.origin.z();
  const double z = scene.groundZ(l.center.head<2>(), fallback) + 0.02;
  const double x = l.center.x(), y = l.center.y();
  const auto corners = texturedQuad({scene.local({x - half, y - half, z}), scene.local({x + half, y - half, z}),
                                     scene.local({x + half, y + half, z}), scene.local({x - half, y + half, z})});
  if (!quad_) quad_ = std::make_unique<GpuMesh>();
  quad_->upload(std::span<const TexturedVertex>(corners));
}

void LandscapeLayer::draw(const DrawContext& context) const {
  if (!empty_) drawTextured(context, *quad_, *texture_, Eigen::Vector4f::Ones());
}

std::optional<ColourScale> LandscapeLayer::colourScale() const {
  if (empty_) return std::nullopt;
  return ColourScale{"NDT score, higher = better", low_, high_, "", false, turbo};
}

std::vector<LayerOption> LandscapeLayer::options() { return {LayerOption::choice("texels", &smooth_, {"cells", "smooth"}, true)}; }

}  // namespace hdprior::render
