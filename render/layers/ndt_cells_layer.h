#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The drivable area's NDT cells near the ego as 2-sigma ellipses on the ground: the map side of
// the scan-to-map matching. Draws nothing when the map was loaded without NDT grids.
class NdtCellsLayer : public Layer {
 public:
  static constexpr const char* kName = "ndt_cells";
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> lines_;
  int grid_ = 0;  // 0 finest, 1 next coarser, ...
  float radius_ = 40.0f;
  Eigen::Vector4f color_{0.45f, 0.95f, 0.55f, 0.35f};
};

}  // namespace hdprior::render
