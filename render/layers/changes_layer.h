#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"
#include "render/layers/stroke_meshes.h"

namespace hdprior::render {

// The map check (Analysis::changes): each drivable area's boundary stretches coloured by verdict
// (contradicted thick, consistent thin, unobserved faint), the missing surfaces' outlines, the
// crossings and lane lines by verdict, optionally what the lidar saw as road and beside the road
// under them with the painted cells the paint checks read (on the map's paint or off it), and a simulated log's labelled changes (where its map really differs) thin in cyan.
class ChangesLayer : public Layer {
 public:
  static constexpr const char* kName = "changes";
  std::string name() const override { return kName; }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::vector<MarkerKey> markerKeys() const override;

 private:
  void build(const Scene& scene);

  const Analysis* analysis_ = nullptr;
  StrokeMeshes strokes_;
  std::unique_ptr<GpuMesh> surface_;
  int show_ = 1;  // 0: verdicts, 1: verdicts and the lidar's surface, 2: also the unobserved stretches
  int labels_ = 1;  // a simulated log's labelled changes: 0 hidden, 1 shown
  Eigen::Vector4f contradicted_{1.0f, 0.15f, 0.15f, 1.0f}, consistent_{0.25f, 0.95f, 0.35f, 1.0f},
      unobserved_{0.6f, 0.6f, 0.6f, 0.5f}, undecided_{1.0f, 0.95f, 0.1f, 1.0f}, missing_{1.0f, 0.2f, 1.0f, 1.0f}, labelled_{0.1f, 0.95f, 0.95f, 1.0f};
  Eigen::Vector4f road_{0.3f, 0.5f, 0.95f, 0.4f}, notRoad_{0.2f, 0.55f, 0.25f, 0.45f};
  Eigen::Vector4f paintOnMap_{1.0f, 1.0f, 1.0f, 0.9f}, paintOffMap_{1.0f, 0.6f, 0.1f, 0.9f};
};

}  // namespace hdprior::render
