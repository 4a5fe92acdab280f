#pragma once
#include <map>
#include <memory>
#include <vector>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The sweeps within `window` frames before and after the current one (not the current one,
// which is the sweep layer's), each placed with its ground-truth pose: a local map built from
// the poses. Coloured vertices are cached per sweep, so stepping one frame colours one sweep.
class AccumulatedSweepsLayer : public Layer {
 public:
  static constexpr const char* kName = "accumulated";
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::optional<ColourScale> colourScale() const override;
  size_t pointCount() const override { return points_ ? points_->size() : 0; }

  void setWindow(int window) { window_ = window; }

 private:
  std::unique_ptr<GpuMesh> points_;
  int window_ = 5;
  int coloring_ = 0;  // SweepColoring
  float pointSize_ = 1.0f;
  int cachedColoring_ = -1;
  std::map<size_t, std::vector<ColoredVertex>> cache_;  // frame index -> vertices
};

}  // namespace hdprior::render
