#pragma once
#include <cstddef>
#include <span>

#include <Eigen/Core>

namespace hdprior {

class NdtGrid;

// Which NDT cells a transformed point is scored against.
enum class NdtLookup {
  ContainingCell,  // the one cell holding the point (fastest)
  FourNearest,     // the 2x2 cells whose centres surround the point (smoother; like Biber's
                   // four overlapping grids)
  Bilinear,        // the same 2x2 cells weighted bilinearly by the point's place between their centres:
                   // the score is continuous where the other two jump as points cross cell lines
                   // (Magnusson's trilinear interpolation, in 2-D)
};

struct NdtScoreParams {
  double outlierRatio = 0.55;  // share of points assumed not to follow the map (PCL's default)
  NdtLookup lookup = NdtLookup::ContainingCell;
};

// The Gaussian approximation of the normal-plus-uniform mixture (Biber & Strasser 2003,
// Magnusson 2009 eq. 6.8): a point at offset q from a cell mean scores
// -d1 * exp(-d2 / 2 * q^T Sigma^-1 q). c1 = 10 (1 - outlierRatio), c2 = outlierRatio / cellSize^2.
struct NdtGaussConstants {
  double d1 = 0, d2 = 0;
};
NdtGaussConstants ndtGaussConstants(double outlierRatio, double cellSize);

// The NDT score of points (ego or key-frame frame) placed on the map by the SE(2) pose
// (x, y, yaw): p -> R(yaw) p + (x, y). Higher is better; the matcher maximises it, e.g. by
// Newton steps delta = -hessian^-1 gradient. Derivatives are with respect to (x, y, yaw).
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
