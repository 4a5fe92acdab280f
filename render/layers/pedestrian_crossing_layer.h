#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The pedestrian crossings of the vector map: translucent quads between their two edges,
// outlined.
class PedestrianCrossingLayer : public Layer {
 public:
  static constexpr const char* kName = "crossings";
  std::string name() const override { return kName; }
  void setScene(const Scene& scene) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> fill_, outline_;
  Eigen::Vector4f color_{0.95f, 0.45f, 0.85f, 0.9f};
};

}  // namespace hdprior::render
