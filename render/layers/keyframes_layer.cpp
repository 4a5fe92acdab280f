#include "render/layers/keyframes_layer.h"

#include <vector>

#include "render/analysis.h"
#include "render/layers/analysis_drawing.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

KeyframesLayer::KeyframesLayer() {
  for (size_t c = 0; c < kConstraintClasses; ++c) colours_[c] = constraintColour(ConstraintClass(c));
}

void KeyframesLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  std::vector<ColoredVertex> dots, ring;
  for (size_t c = 0; c < kConstraintClasses; ++c) {
    for (const KeyframeMark& mark : analysis.keyframes)
      if (constraintClass(mark.constraint) == ConstraintClass(c))
        dots.push_back({scene.local(mark.pose.translation()), Eigen::Vector4f::Ones()});
    rangeEnd_[c] = dots.size();
  }
  if (analysis.inspection && analysis.inspection->keyframe < analysis.keyframes.size())
    ring.push_back({scene.local(analysis.keyframes[analysis.inspection->keyframe].pose.translation()), Eigen::Vector4f::Ones()});
  if (!dots_) {
    dots_ = std::make_unique<GpuMesh>();
    highlight_ = std::make_unique<GpuMesh>();
  }
  dots_->upload(std::span<const ColoredVertex>(dots));
  highlight_->upload(std::span<const ColoredVertex>(ring));
}

void KeyframesLayer::draw(const DrawContext& context) const {
  if (!dots_) return;
  if (highlight_->size() > 0) drawColored(context, *highlight_, Primitive::Points, 2.0f * size_, true, highlightColor_);
  std::array<const Eigen::Vector4f*, kConstraintClasses> colours;
  for (size_t c = 0; c < kConstraintClasses; ++c) colours[c] = &colours_[c];
  drawRanges(context, *dots_, Primitive::Points, size_, true, rangeEnd_, colours);
}

std::vector<LayerOption> KeyframesLayer::options() {
  std::vector<LayerOption> o = {LayerOption::slider("size", &size_, 2.0f, 16.0f)};
  for (size_t c = 0; c < kConstraintClasses; ++c) o.push_back(LayerOption::colorPicker(kConstraintClassNames[c], &colours_[c]));
  o.push_back(LayerOption::colorPicker("inspected", &highlightColor_));
  return o;
}

// The classes the run has, so that the legend says what each dot's colour means.
std::vector<MarkerKey> KeyframesLayer::markerKeys() const {
  std::vector<MarkerKey> keys;
  for (size_t c = 0, first = 0; c < kConstraintClasses; first = rangeEnd_[c++])
    if (rangeEnd_[c] > first) keys.push_back({std::string("keyframe: ") + kConstraintClassNames[c], colours_[c]});
  return keys;
}

}  // namespace hdprior::render
