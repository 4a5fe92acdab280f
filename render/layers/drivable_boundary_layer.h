#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The curb points of the drivable raster (its boundary sampled every cell), on the ground.
class DrivableBoundaryLayer : public Layer {
 public:
  static constexpr const char* kName = "boundary";
  std::string name() const override { return kName; }
  void setScene(const Scene& scene) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> points_;
  Eigen::Vector4f color_{1.0f, 0.72f, 0.10f, 1.0f};
  float pointSize_ = 2.0f;
};

}  // namespace hdprior::render
