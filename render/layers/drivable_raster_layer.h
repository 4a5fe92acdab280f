#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/gpu_texture.h"
#include "render/layer.h"

namespace hdprior::render {

// The drivable raster as a translucent texture on a flat quad under the ego.
class DrivableRasterLayer : public Layer {
 public:
  static constexpr const char* kName = "drivable";
  std::string name() const override { return kName; }
  void setScene(const Scene& scene) override;
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuTexture> texture_;
  std::unique_ptr<GpuMesh> quad_;
  Eigen::Vector4f color_{0.59f, 0.63f, 0.69f, 0.45f};
};

}  // namespace hdprior::render
