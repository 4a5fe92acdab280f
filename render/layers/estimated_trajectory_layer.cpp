#include "render/layers/estimated_trajectory_layer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/analysis.h"
#include "render/colormap.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {

namespace {

struct Kind {
  const char* name;
  const char* scaleLabel;
  Eigen::Vector4f color;
};

const Kind& kind(EstimatedTrajectoryLayer::Which which) {
  using L = EstimatedTrajectoryLayer;
  static const Kind kinds[] = {{L::kOdometryName, "odometry ATE", {1.0f, 0.45f, 0.15f, 1.0f}},
                               {L::kOptimizedName, "optimised ATE", {0.25f, 0.55f, 1.0f, 1.0f}},
                               {L::kFileName, "file ATE", {0.9f, 0.3f, 0.9f, 1.0f}},
                               {L::kComparisonName, "B ATE", {0.3f, 1.0f, 0.75f, 1.0f}}};
  return kinds[int(which)];
}

}  // namespace

EstimatedTrajectoryLayer::EstimatedTrajectoryLayer(Which which) : which_(which), color_(kind(which).color) {}

std::string EstimatedTrajectoryLayer::name() const { return kind(which_).name; }

const PoseTrajectory& EstimatedTrajectoryLayer::trajectory() const {
  static const PoseTrajectory none;
  switch (which_) {
    case Which::Odometry: return analysis_->odometry;
    case Which::Optimized: return analysis_->optimized;
    case Which::File: return analysis_->file;
    case Which::Comparison: break;
  }
  return analysis_->comparison ? analysis_->comparison->optimized : none;
}

const std::vector<double>& EstimatedTrajectoryLayer::errors() const {
  static const std::vector<double> none;
  switch (which_) {
    case Which::Odometry: return analysis_->odometryError;
    case Which::Optimized: return analysis_->optimizedError;
    case Which::File: return analysis_->fileError;
    case Which::Comparison: break;
  }
  return analysis_->comparison ? analysis_->comparison->optimizedError : none;
}

void EstimatedTrajectoryLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  analysis_ = &analysis;
  build(scene);
}

void EstimatedTrajectoryLayer::build(const Scene& scene) {
  if (!line_) line_ = std::make_unique<GpuMesh>();
  std::vector<ColoredVertex> vertices;
  if (analysis_) {
    const PoseTrajectory& trajectory = this->trajectory();
    const std::vector<double>& errors = this->errors();
    double top = errorMax_;
    if (!(top > 0)) {
      for (double e : errors)
        if (std::isfinite(e)) top = std::max(top, e);
    }
    top_ = std::max(top, 1e-6);
    for (size_t i = 0; i < trajectory.size(); ++i) {
      Eigen::Vector4f c = Eigen::Vector4f::Ones();
      if (byError_) {
        const double e = i < errors.size() ? errors[i] : NAN;
        c = std::isfinite(e) ? Eigen::Vector4f(turbo(float(e / top_)).homogeneous())
                             : Eigen::Vector4f(0.5f, 0.5f, 0.5f, 1.0f);
      }
      vertices.push_back({scene.local(trajectory.poses()[i].translation()), c});
    }
  }
  line_->upload(std::span<const ColoredVertex>(vertices));
}

void EstimatedTrajectoryLayer::draw(const DrawContext& context) const {
  if (!line_ || line_->size() == 0) return;
  const Eigen::Vector4f tint = byError_ ? Eigen::Vector4f::Ones() : color_;
  drawColored(context, *line_, Primitive::LineStrip, 1.0f, false, tint);
  drawColored(context, *line_, Primitive::Points, 3.0f, true, tint);
}

std::optional<ColourScale> EstimatedTrajectoryLayer::colourScale() const {
  if (!byError_ || !line_ || line_->size() == 0) return std::nullopt;
  return ColourScale{kind(which_).scaleLabel, 0.0, top_, "m", false, turbo};
}

std::vector<LayerOption> EstimatedTrajectoryLayer::options() {
  LayerOption range = LayerOption::slider("error range (m, 0: largest)", &errorMax_, 0.0f, 5.0f);
  range.rebuilds = true;
  return {LayerOption::choice("colour by", &byError_, {"own colour", "error (ATE)"}, true), range,
          LayerOption::colorPicker("colour", &color_)};
}

}  // namespace hdprior::render
