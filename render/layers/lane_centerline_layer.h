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
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> lines_;
  size_t laneVertices_ = 0;  // the first vertices are lanes outside intersections
  Eigen::Vector4f laneColor_{1.0f, 1.0f, 1.0f, 0.85f};
  Eigen::Vector4f intersectionColor_{0.85f, 0.85f, 1.0f, 0.45f};
};

}  // namespace hdprior::render
