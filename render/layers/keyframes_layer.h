#pragma once
#include <array>
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// A dot per keyframe at its final pose, coloured by what its match did (accepted, degenerate,
// rejected, no prior), the inspected keyframe ringed.
class KeyframesLayer : public Layer {
 public:
  static constexpr const char* kName = "keyframes";
  std::string name() const override { return kName; }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;

 private:
  std::unique_ptr<GpuMesh> dots_, highlight_;
  std::array<size_t, 4> rangeEnd_{};  // dots by status: accepted, degenerate, rejected, none
  float size_ = 7.0f;
  Eigen::Vector4f accepted_{0.20f, 0.85f, 0.30f, 1.0f}, degenerate_{1.00f, 0.70f, 0.10f, 1.0f},
      rejected_{0.95f, 0.20f, 0.20f, 1.0f}, none_{0.60f, 0.60f, 0.60f, 1.0f}, highlightColor_{1.0f, 1.0f, 1.0f, 1.0f};
};

}  // namespace hdprior::render
