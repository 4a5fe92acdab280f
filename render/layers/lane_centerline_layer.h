#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The centerlines of the lane graph as lines (intersection lanes fainter).
class LaneCenterlineLayer : public Layer {
 public:
  static constexpr const char* kName = "lanes";
  std::string name() const override { return kName; }
  void setScene(const Scene& scene) override;
  void draw(const DrawContext& context) const override;

 private:
  std::unique_ptr<GpuMesh> lines_;
};

}  // namespace hdprior::render
