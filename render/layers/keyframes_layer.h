#pragma once
#include <array>
#include <memory>

#include "render/constraint_palette.h"
#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// A dot per keyframe at its final pose, coloured by what its prior fixes (full, partial such as
// lateral + yaw, gated, rejected, no prior), the inspected keyframe ringed.
class KeyframesLayer : public Layer {
 public:
  static constexpr const char* kName = "keyframes";
  KeyframesLayer();
  std::string name() const override { return kName; }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::vector<MarkerKey> markerKeys() const override;

 private:
  std::unique_ptr<GpuMesh> dots_, highlight_;
  std::array<size_t, kConstraintClasses> rangeEnd_{};  // dots by ConstraintClass
  std::array<Eigen::Vector4f, kConstraintClasses> colours_;
  float size_ = 7.0f;
  Eigen::Vector4f highlightColor_{1.0f, 1.0f, 1.0f, 1.0f};
};

}  // namespace hdprior::render
