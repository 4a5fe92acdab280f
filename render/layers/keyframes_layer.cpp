#include "render/layers/keyframes_layer.h"

#include <vector>

#include "render/analysis.h"
#include "render/layers/analysis_drawing.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {
namespace {

int statusIndex(const std::optional<MatchStatus>& status) {
  if (!status) return 3;
  return *status == MatchStatus::Accepted ? 0 : *status == MatchStatus::Degenerate ? 1 : 2;
}

}  // namespace

void KeyframesLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  std::vector<ColoredVertex> dots, ring;
  for (int s = 0; s < 4; ++s) {
    for (const KeyframeMark& mark : analysis.keyframes)
      if (statusIndex(mark.status) == s) dots.push_back({scene.local(mark.pose.translation()), Eigen::Vector4f::Ones()});
    rangeEnd_[size_t(s)] = dots.size();
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
  const Eigen::Vector4f* colors[] = {&accepted_, &degenerate_, &rejected_, &none_};
  drawRanges(context, *dots_, Primitive::Points, size_, true, rangeEnd_, colors);
}

std::vector<LayerOption> KeyframesLayer::options() {
  return {LayerOption::slider("size", &size_, 2.0f, 16.0f), LayerOption::colorPicker("accepted", &accepted_),
          LayerOption::colorPicker("degenerate", &degenerate_), LayerOption::colorPicker("rejected", &rejected_),
          LayerOption::colorPicker("no prior", &none_), LayerOption::colorPicker("inspected", &highlightColor_)};
}

}  // namespace hdprior::render
