#pragma once
#include <memory>
#include <vector>

#include "engine/geom/pose_trajectory.h"
#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The odometry's, the optimised, an opened trajectory file's or run B's trajectory of the analysis (the
// ground truth is TrajectoryLayer) as a line strip with pose dots, in its own colour or coloured by its per-pose ATE (Turbo from
// 0 to the largest error, or to a fixed maximum).
class EstimatedTrajectoryLayer : public Layer {
 public:
  enum class Which { Odometry, Optimized, File, Comparison };
  static constexpr const char* kOdometryName = "odometry_trajectory";
  static constexpr const char* kOptimizedName = "optimized_trajectory";
  static constexpr const char* kFileName = "file_trajectory";
  static constexpr const char* kComparisonName = "comparison_trajectory";  // run B of an A/B comparison
  explicit EstimatedTrajectoryLayer(Which which);
  std::string name() const override;
  void setFrame(const Scene& scene, const Frame& frame) override { build(scene); }
  void setAnalysis(const Scene& scene, const Analysis& analysis) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::optional<ColourScale> colourScale() const override;

 private:
  void build(const Scene& scene);
  const PoseTrajectory& trajectory() const;
  const std::vector<double>& errors() const;

  Which which_;
  const Analysis* analysis_ = nullptr;
  std::unique_ptr<GpuMesh> line_;
  int byError_ = 0;
  float errorMax_ = 0.0f;  // metres at the top of the colour map; 0: the largest error
  double top_ = 0.0;       // the error drawn at the top of the colour map
  Eigen::Vector4f color_;
};

}  // namespace hdprior::render
