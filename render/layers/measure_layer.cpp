#include "render/layers/measure_layer.h"

#include <cmath>
#include <vector>

#include "render/analysis.h"
#include "render/layers/analysis_drawing.h"
#include "render/layers/stroke_meshes.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

void MeasureLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  analysis_ = &analysis;
  build(scene);
}

void MeasureLayer::build(const Scene& scene) {
  Strokes strokes;
  std::vector<ColoredVertex> dots;
  if (analysis_ && analysis_->measure) {
    const GroundMeasure& m = *analysis_->measure;
    const double z = std::max(m.from.z(), m.to.z()) + 0.08;
    const auto at = [&](const Eigen::Vector3d& p) { return scene.local({p.x(), p.y(), z}); };
    // The legs meet where the along component ends.
    const Eigen::Vector3d corner(m.from.x() + m.along * std::cos(m.heading), m.from.y() + m.along * std::sin(m.heading), z);
    strokes.segment(at(m.from), at(corner), 0.5f * width_, along_);
    strokes.segment(at(corner), at(m.to), 0.5f * width_, lateral_);
    strokes.segment(at(m.from), at(m.to), width_, line_);
    dots.push_back({at(m.from), line_});
    dots.push_back({at(m.to), line_});
  }
  meshes_.upload(strokes, dots);
}

void MeasureLayer::draw(const DrawContext& context) const {
  meshes_.draw(context, 9.0f);
}

std::vector<MarkerKey> MeasureLayer::markerKeys() const {
  if (!analysis_ || !analysis_->measure) return {};
  return {{"measure", line_}, {"along heading", along_}, {"across heading", lateral_}};
}

std::vector<LayerOption> MeasureLayer::options() {
  std::vector<LayerOption> o = {LayerOption::slider("line width (m)", &width_, 0.01f, 0.5f)};
  for (auto [label, color] : {std::pair{"line", &line_}, {"along", &along_}, {"across", &lateral_}})
    o.push_back(LayerOption::colorPicker(label, color));
  for (LayerOption& option : o) option.rebuilds = true;
  return o;
}

}  // namespace hdprior::render
