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

 private:
  std::unique_ptr<GpuMesh> line_;
};

}  // namespace hdprior::render
