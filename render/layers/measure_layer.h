#pragma once
#include <memory>

#include "render/layers/stroke_meshes.h"
#include "render/layer.h"

namespace hdprior::render {

// The user's measurement between two ground points: the segment, its components along and across
// the ego heading (a right-angle pair of legs), and a dot at each end.
class MeasureLayer : public Layer {
 public:
  static constexpr const char* kName = "measure";
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override { build(scene); }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::vector<MarkerKey> markerKeys() const override;

 private:
  void build(const Scene& scene);

  const Analysis* analysis_ = nullptr;
  StrokeMeshes meshes_;
  float width_ = 0.06f;  // metres
  Eigen::Vector4f line_{1.0f, 1.0f, 0.2f, 1.0f}, along_{0.3f, 0.9f, 1.0f, 0.9f}, lateral_{1.0f, 0.4f, 0.6f, 0.9f};
};

}  // namespace hdprior::render
