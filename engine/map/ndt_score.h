#pragma once
#include <cstddef>
#include <span>

#include <Eigen/Core>

namespace hdprior {

class NdtGrid;

struct NdtScoreParams {
  double outlierRatio = 0.55;  // share of points assumed not to follow the map (PCL's default)
};

// The Gaussian approximation of the normal-plus-uniform mixture (Biber & Strasser 2003,
// Magnusson 2009 eq. 6.8): a point at offset q from a cell mean scores
// -d1 * exp(-d2 / 2 * q^T Sigma^-1 q). c1 = 10 (1 - outlierRatio), c2 = outlierRatio / cellSize^2.
struct NdtGaussConstants {
  double d1 = 0, d2 = 0;
};
NdtGaussConstants ndtGaussConstants(double outlierRatio, double cellSize);

// The NDT score of points (ego or key-frame frame) placed on the map by the SE(2) pose
// (x, y, yaw): p -> R(yaw) p + (x, y). Each point is scored against the 2 x 2 cells whose centres
// surround it (smoother than the one cell holding it: like Biber's four overlapping grids); each
// term lies in [0, |d1|] (d1 < 0). Higher is better; the matcher maximises it, e.g. by Newton steps
// delta = -hessian^-1 gradient. Derivatives are with respect to (x, y, yaw).
struct NdtScore {
  double score = 0.0;
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
  size_t matched = 0;  // point-to-cell terms that contributed (points outside any valid cell add 0)
};

enum class NdtDerivatives { None, Gradient, GradientAndHessian };

NdtScore scoreNdt(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& pose,
                  const NdtScoreParams& params = {},
                  NdtDerivatives derivatives = NdtDerivatives::GradientAndHessian);

}  // namespace hdprior
