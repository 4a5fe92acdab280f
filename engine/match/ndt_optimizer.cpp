#include "engine/match/ndt_optimizer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "engine/geom/angles.h"
#include "engine/map/ndt_grid.h"
#include "engine/map/ndt_score.h"

namespace hdprior {
namespace {

// An ascent direction: (-H)^-1 g with -H's eigenvalues (in scaled units) lifted to a floor.
Eigen::Vector3d ascentDirection(const NdtScore& s, double yawLength) {
  const Eigen::Vector3d d(1.0, 1.0, yawLength);  // scaled = D * pose
  const Eigen::Matrix3d A = -(d.cwiseInverse().asDiagonal() * s.hessian * d.cwiseInverse().asDiagonal());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (A + A.transpose()));
  Eigen::Vector3d lambda = eig.eigenvalues();
  const double floor = std::max(1e-3 * std::abs(lambda.maxCoeff()), 1e-9);
  lambda = lambda.cwiseMax(floor);
  const Eigen::Vector3d gScaled = d.cwiseInverse().asDiagonal() * s.gradient;
  const Eigen::Vector3d stepScaled = eig.eigenvectors() * (eig.eigenvectors().transpose() * gScaled).cwiseQuotient(lambda);
  return d.cwiseInverse().asDiagonal() * stepScaled;
}

// The four-cell score is rough: its local curvature overstates the trend, so full Newton steps
// often gain more than their quadratic model predicts and crawl. A full step that gained
// `gainRatio` times its linear prediction (1/2 on the model) measures the curvature along it;
// the next step is lengthened (or shortened) towards where that 1-D parabola peaks.
double nextStepGain(double gain, double gainRatio, double maxGain) {
  const double peak = gainRatio >= 0.75 ? 2.0 : 1.0 / (2.0 * (1.0 - gainRatio));
  return std::clamp(gain * std::clamp(peak, 0.5, 2.0), 1.0, maxGain);
}

}  // namespace

NdtOptimization optimizeNdt(const std::vector<const NdtGrid*>& levels, std::span<const Eigen::Vector2d> all,
                            const Eigen::Vector3d& initial, const MatchOptions& o,
                            std::chrono::steady_clock::time_point deadline) {
  NdtOptimization result;
  result.pose = initial;
  result.path.push_back(initial);
  const NdtScoreParams params{.outlierRatio = o.outlierRatio};
  std::vector<Eigen::Vector2d> subset;
  const double finest = levels.empty() ? 1.0 : levels.back()->cellSize();
  for (const NdtGrid* grid : levels) {
    // Coarser grids need fewer points: every (size / finest)^2-th one (capped by coarseStride).
    const double ratio = grid->cellSize() / finest;
    const size_t stride = std::clamp<size_t>(size_t(std::lround(ratio * ratio)), 1, size_t(o.maxCoarseStride));
    std::span<const Eigen::Vector2d> points = all;
    if (stride > 1 && all.size() / stride >= size_t(o.minPoints)) {
      subset.clear();
      for (size_t i = 0; i < all.size(); i += stride) subset.push_back(all[i]);
      points = subset;
    }
    Eigen::Vector3d x = result.pose;
    NdtScore s = scoreNdt(*grid, points, x, params);
    const double maxStep = o.maxStepCells * grid->cellSize(), maxYaw = o.maxStepYawDeg * kDegree;
    // A coarse level only seeds the next one: its tolerances grow with its cell size.
    const double tolerance = o.translationTolerance * ratio, yawTolerance = o.yawToleranceDeg * kDegree * ratio;
    double gain = 1.0;  // the Newton step's length factor, learnt along the way
    for (int it = 0; it < o.maxIterations; ++it) {
      if (std::chrono::steady_clock::now() > deadline) {
        result.timedOut = true;
        result.pose = x;
        return result;
      }
      Eigen::Vector3d step = gain * ascentDirection(s, o.yawLength);
      const double scale = std::min({1.0, maxStep / std::max(step.head<2>().norm(), 1e-12),
                                     maxYaw / std::max(std::abs(step.z()), 1e-12)});
      step *= scale;
      const double slope = s.gradient.dot(step);
      if (!(slope > 0.0)) break;
      // The full step usually passes, so it is scored with derivatives at once (they are
      // the next iteration's); shorter steps are scored alone first.
      bool moved = false;
      for (double alpha = 1.0; alpha > 1.0 / 64; alpha *= 0.5) {
        const Eigen::Vector3d candidate = x + alpha * step;
        const NdtDerivatives what = alpha == 1.0 ? NdtDerivatives::GradientAndHessian : NdtDerivatives::None;
        NdtScore trial = scoreNdt(*grid, points, candidate, params, what);
        if (trial.score >= s.score + 1e-4 * alpha * slope) {
          gain = alpha == 1.0 ? nextStepGain(gain, (trial.score - s.score) / slope, o.maxStepGain)
                              : std::max(1.0, gain * alpha);
          x = candidate;
          step *= alpha;
          moved = true;
          s = what == NdtDerivatives::None ? scoreNdt(*grid, points, x, params) : trial;
          break;
        }
      }
      ++result.iterations;
      result.path.push_back(x);
      if (!moved) break;
      if (step.head<2>().norm() < tolerance && std::abs(step.z()) < yawTolerance) break;
    }
    result.pose = x;
  }
  return result;
}

}  // namespace hdprior
