#pragma once
#include <memory>

#include "render/layers/stroke_meshes.h"
#include "render/layer.h"

namespace hdprior {
struct KeyframeInspection;
}

namespace hdprior::render {

// The inspected keyframe's match: its start, the iteration path (a dot per iterate), the
// result and the ground truth as pose markers with a heading tick, and the 2-sigma ellipse of
// the covariance's x-y block at the result. A direction the match does not observe (along a
// straight road) is drawn at the length limit. The comparison's instance draws run B's match of the
// same keyframe in its own colours (no truth: A's shows it).
class MatchLayer : public Layer {
 public:
  static constexpr const char* kName = "match";
  static constexpr const char* kComparisonName = "comparison_match";
  explicit MatchLayer(bool comparison = false);
  std::string name() const override { return comparison_ ? kComparisonName : kName; }
  void setFrame(const Scene& scene, const Frame& frame) override { build(scene); }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::vector<MarkerKey> markerKeys() const override;

 private:
  void build(const Scene& scene);
  const KeyframeInspection* inspection() const;

  bool comparison_ = false;
  const Analysis* analysis_ = nullptr;
  StrokeMeshes meshes_;
  float width_ = 0.05f;       // metres
  float tick_ = 1.5f;         // heading tick length, metres
  float maxHalfAxis_ = 10.0f;  // metres
  float dotSize_ = 6.0f;
  Eigen::Vector4f start_{1.0f, 0.55f, 0.10f, 1.0f}, path_{1.0f, 0.95f, 0.25f, 1.0f}, estimate_{0.2f, 0.9f, 1.0f, 1.0f},
      truth_{0.3f, 1.0f, 0.4f, 1.0f}, ellipse_{1.0f, 0.35f, 0.9f, 1.0f};
};

}  // namespace hdprior::render
