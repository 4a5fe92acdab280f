#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The ground-truth trajectory (city_T_ego of the whole log) as a line strip with pose dots.
class TrajectoryLayer : public Layer {
 public:
  static constexpr const char* kName = "trajectory";
  std::string name() const override { return kName; }
  void setScene(const Scene& scene) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> line_;
  Eigen::Vector4f color_{0.15f, 0.95f, 0.35f, 1.0f};
};

}  // namespace hdprior::render
