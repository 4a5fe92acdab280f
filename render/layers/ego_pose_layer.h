#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The ego vehicle at its ground-truth pose: a translucent footprint with a heading arrow.
class EgoPoseLayer : public Layer {
 public:
  static constexpr const char* kName = "ego";
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> triangles_;
  Eigen::Vector4f bodyColor_{0.95f, 0.15f, 0.15f, 0.75f};
};

}  // namespace hdprior::render
