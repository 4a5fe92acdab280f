#include "render/layers/match_layer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "render/analysis.h"
#include "render/layers/analysis_drawing.h"
#include "render/layers/stroke_meshes.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {
namespace {

// The 2-sigma half-axes of the estimate's x-y covariance; a direction without information (the
// covariance is a pseudo-inverse: zero there) gets maxHalfAxis, every axis at most that.
Eigen::Matrix2f clampedAxes(const MatchResult& m, double maxHalfAxis) {
  const Eigen::Matrix2d information = m.information.topLeftCorner<2, 2>();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(m.covariance.topLeftCorner<2, 2>());
  Eigen::Matrix2f axes;
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d v = eig.eigenvectors().col(i);
    const bool observed = v.dot(information * v) > 1e-9 * std::max(information.norm(), 1e-12);
    const double half = observed ? 2.0 * std::sqrt(std::max(eig.eigenvalues()(i), 0.0)) : maxHalfAxis;
    axes.col(i) = (v * std::min(half, maxHalfAxis)).cast<float>();
  }
  return axes;
}

}  // namespace

MatchLayer::MatchLayer(bool comparison) : comparison_(comparison) {
  if (!comparison) return;
  start_ = {0.45f, 0.75f, 0.6f, 1.0f};
  path_ = {0.65f, 0.9f, 0.8f, 1.0f};
  estimate_ = {0.3f, 1.0f, 0.75f, 1.0f};  // run B's colour, as its trajectory
  ellipse_ = {0.2f, 0.8f, 0.6f, 1.0f};
}

const KeyframeInspection* MatchLayer::inspection() const {
  if (!analysis_) return nullptr;
  if (!comparison_) return analysis_->inspection ? &*analysis_->inspection : nullptr;
  const auto& b = analysis_->comparison;
  return b && b->inspection ? &*b->inspection : nullptr;
}

void MatchLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  analysis_ = &analysis;
  build(scene);
}

void MatchLayer::build(const Scene& scene) {
  Strokes strokes;
  std::vector<ColoredVertex> dots;
  if (const KeyframeInspection* inspected = inspection()) {
    const KeyframeInspection& k = *inspected;
    const double z = k.keyframePose.translation().z() + 0.05;
    const auto at = [&](const Eigen::Vector3d& pose) { return scene.local({pose.x(), pose.y(), z}); };
    const auto marker = [&](const Eigen::Vector3d& pose, const Eigen::Vector4f& color) {
      const Eigen::Vector3d ahead = pose + tick_ * Eigen::Vector3d(std::cos(pose.z()), std::sin(pose.z()), 0.0);
      strokes.segment(at(pose), at(ahead), 2.0f * width_, color);
      dots.push_back({at(pose), color});
    };
    if (k.match.status != MatchStatus::Rejected)
      strokes.polyline(ellipseLoop(at(k.match.estimate), clampedAxes(k.match, maxHalfAxis_)), width_, ellipse_);
    std::vector<Eigen::Vector3f> path;
    for (const Eigen::Vector3d& pose : k.match.path) {
      path.push_back(at(pose));
      dots.push_back({at(pose), path_});
    }
    strokes.polyline(path, width_, path_);
    marker(k.start, start_);
    if (k.truth && !comparison_) marker(*k.truth, truth_);
    marker(k.match.estimate, estimate_);
  }
  meshes_.upload(strokes, dots);
}

void MatchLayer::draw(const DrawContext& context) const {
  meshes_.draw(context, dotSize_);
}

std::vector<MarkerKey> MatchLayer::markerKeys() const {
  const KeyframeInspection* k = inspection();
  if (!k) return {};
  if (comparison_) return {{"B start", start_}, {"B estimate", estimate_}};
  std::vector<MarkerKey> keys = {{"start", start_}, {"estimate", estimate_}};
  if (k->truth) keys.push_back({"truth", truth_});
  return keys;
}

std::vector<LayerOption> MatchLayer::options() {
  std::vector<LayerOption> o = {LayerOption::slider("line width (m)", &width_, 0.01f, 0.5f),
                                LayerOption::slider("heading tick (m)", &tick_, 0.2f, 5.0f),
                                LayerOption::slider("ellipse limit (m)", &maxHalfAxis_, 1.0f, 30.0f),
                                LayerOption::slider("dot size", &dotSize_, 2.0f, 16.0f)};
  for (LayerOption& option : o) option.rebuilds = option.label != "dot size";
  for (auto [label, color] : {std::pair{"start", &start_}, {"path", &path_}, {"estimate", &estimate_},
                              {"truth", &truth_}, {"covariance", &ellipse_}}) {
    LayerOption c = LayerOption::colorPicker(label, color);
    c.rebuilds = true;
    o.push_back(c);
  }
  return o;
}

}  // namespace hdprior::render
