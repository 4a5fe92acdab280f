#pragma once
#include <array>
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The current sweep's ground segmentation (or its road points) against reference per-point ground
// labels (Scene::groundLabels: Argoverse 2 scene flow's is_ground_0, given for one frame): ground
// both agree on, ground the reference lacks (false), reference ground missed (missed), and the
// rest. Draws nothing on other frames.
class GroundLabelsLayer : public Layer {
 public:
  static constexpr const char* kName = "ground_labels";
  enum Compared { GroundSegmentation = 0, RoadPoints = 1 };
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::vector<MarkerKey> markerKeys() const override;
  size_t pointCount() const override { return points_ ? points_->size() : 0; }

 private:
  enum Agreement { Neither = 0, Both = 1, Missed = 2, False = 3 };  // drawing order: the errors on top
  std::unique_ptr<GpuMesh> points_;
  std::array<size_t, 4> counts_{};
  int compared_ = GroundSegmentation;
  float pointSize_ = 2.0f;
};

}  // namespace hdprior::render
