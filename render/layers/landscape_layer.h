#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/gpu_texture.h"
#include "render/layer.h"

namespace hdprior::render {

// The cost landscape as a heat map on the ground around its centre: each cell the NDT score of
// the road points moved by that (x, y) offset, Turbo from the lowest (blue) to the highest (red).
class LandscapeLayer : public Layer {
 public:
  static constexpr const char* kName = "landscape";
  LandscapeLayer() { opacity = 0.75f; }
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override { build(scene); }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::optional<ColourScale> colourScale() const override;

 private:
  void build(const Scene& scene);

  const Analysis* analysis_ = nullptr;
  std::unique_ptr<GpuMesh> quad_;
  std::unique_ptr<GpuTexture> texture_;
  int smooth_ = 0;
  bool empty_ = true;
  double low_ = 0, high_ = 0;  // the scores at the two ends of the colour map
};

}  // namespace hdprior::render
