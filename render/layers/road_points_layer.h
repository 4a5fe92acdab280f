#pragma once
#include <array>
#include <memory>

#include "render/gpu_mesh.h"
#include "engine/pipeline/keyframe_inspection.h"
#include "render/layer.h"


namespace hdprior::render {

// The inspected keyframe's sub-map coloured by label (road, curb, other ground, and non-ground
// when switched on), placed in the city by the match estimate (or its start, or the truth):
// x, y and yaw from that pose, z from the keyframe's pose.
class RoadPointsLayer : public Layer {
 public:
  static constexpr const char* kName = "road_points";
  enum Placement { AtEstimate = 0, AtStart = 1, AtTruth = 2 };
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override { build(scene); }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  size_t pointCount() const override { return points_ ? points_->size() : 0; }

  void showNonGround(bool on) { nonGround_ = on ? 1 : 0; }

 private:
  void build(const Scene& scene);

  static constexpr std::array<SubmapLabel, 4> kDrawOrder = {SubmapLabel::Other, SubmapLabel::Ground, SubmapLabel::Road,
                                                            SubmapLabel::Curb};
  const KeyframeInspection* inspection_ = nullptr;
  std::array<size_t, 4> rangeEnd_{};  // vertices of kDrawOrder[r] end here
  std::unique_ptr<GpuMesh> points_;
  int placement_ = AtEstimate;
  int nonGround_ = 0;
  float pointSize_ = 2.0f;
  Eigen::Vector4f road_{0.20f, 0.80f, 1.00f, 1.0f}, curb_{1.00f, 0.25f, 0.80f, 1.0f},
      ground_{0.62f, 0.45f, 0.98f, 1.0f}, other_{0.70f, 0.70f, 0.72f, 0.8f};
};

}  // namespace hdprior::render
