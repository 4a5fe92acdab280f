#include "render/layers/accumulated_sweeps_layer.h"

#include <algorithm>

#include "engine/io/argoverse_log.h"
#include "render/layers/layer_drawing.h"
#include "render/layers/sweep_coloring.h"
#include "render/scene.h"

namespace hdprior::render {

void AccumulatedSweepsLayer::setFrame(const Scene& scene, const Frame& frame) {
  if (!points_) points_ = std::make_unique<GpuMesh>();
  if (cachedColoring_ != coloring_) cache_.clear();
  cachedColoring_ = coloring_;
  const size_t count = scene.log->sweepCount();
  const size_t first = frame.index > size_t(window_) ? frame.index - size_t(window_) : 0;
  const size_t last = std::min(count == 0 ? 0 : count - 1, frame.index + size_t(window_));
  std::erase_if(cache_, [&](const auto& entry) { return entry.first < first || entry.first > last; });

  std::vector<ColoredVertex> vertices;
  for (size_t i = first; i <= last && count > 0; ++i) {
    if (i == frame.index) continue;
    auto it = cache_.find(i);
    if (it == cache_.end()) {
      const Frame other = makeFrame(scene, i);
      it = cache_.emplace(i, sweepVertices(scene, *other.sweep, other.cityTEgo, other.groundZ,
                                           SweepColoring(coloring_))).first;
    }
    vertices.insert(vertices.end(), it->second.begin(), it->second.end());
  }
  points_->upload(std::span<const ColoredVertex>(vertices));
}

void AccumulatedSweepsLayer::draw(const DrawContext& context) const {
  if (points_) drawLidarPoints(context, *points_, pointSize_);
}

std::optional<ColourScale> AccumulatedSweepsLayer::colourScale() const {
  return sweepColourScale(SweepColoring(coloring_));
}

std::vector<LayerOption> AccumulatedSweepsLayer::options() {
  return {LayerOption::intSlider("frames before/after", &window_, 1, 25, true),
          LayerOption::choice("colour by", &coloring_, sweepColoringNames(), true),
          LayerOption::slider("point size", &pointSize_, 1.0f, 6.0f)};
}

}  // namespace hdprior::render
