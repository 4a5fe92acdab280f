#include "engine/map/ndt_score.h"

#include <cmath>
#include <string>

#include "engine/error.h"
#include "engine/map/ndt_grid.h"

namespace hdprior {
namespace {

// Running sums of the score terms; the Hessian keeps its 6 distinct entries.
struct Accumulator {
  double score = 0, gx = 0, gy = 0, gt = 0;
  double hxx = 0, hxy = 0, hxt = 0, hyy = 0, hyt = 0, htt = 0;
  size_t matched = 0;
};

// One point-to-cell term (Magnusson 2009, eqs. 6.12-6.13, specialised to SE(2)). (a, b) is
// R(yaw) p, so dq/dx = (1, 0), dq/dy = (0, 1), dq/dyaw = (-b, a), d2q/dyaw2 = (-a, -b).
template <NdtDerivatives D>
inline void addTerm(const NdtCell& cell, double tx, double ty, double a, double b, const NdtGaussConstants& k,
                    Accumulator& acc) {
  const double qx = tx - cell.mean.x(), qy = ty - cell.mean.y();
  const double i00 = cell.information(0, 0), i01 = cell.information(0, 1), i11 = cell.information(1, 1);
  const double u0 = i00 * qx + i01 * qy, u1 = i01 * qx + i11 * qy;  // Sigma^-1 q
  const double e = std::exp(-0.5 * k.d2 * (qx * u0 + qy * u1));
  acc.score -= k.d1 * e;
  ++acc.matched;
  if constexpr (D == NdtDerivatives::None) return;
  const double f = k.d1 * k.d2 * e;
  const double gt = a * u1 - b * u0;  // q^T Sigma^-1 dq/dyaw
  acc.gx += f * u0;
  acc.gy += f * u1;
  acc.gt += f * gt;
  if constexpr (D != NdtDerivatives::GradientAndHessian) return;
  const double w0 = i01 * a - i00 * b, w1 = i11 * a - i01 * b;  // Sigma^-1 dq/dyaw
  const double d2 = k.d2;
  acc.hxx += f * (i00 - d2 * u0 * u0);
  acc.hxy += f * (i01 - d2 * u0 * u1);
  acc.hyy += f * (i11 - d2 * u1 * u1);
  acc.hxt += f * (w0 - d2 * u0 * gt);
  acc.hyt += f * (w1 - d2 * u1 * gt);
  acc.htt += f * ((a * w1 - b * w0) - (a * u0 + b * u1) - d2 * gt * gt);
}

template <NdtDerivatives D>
Accumulator accumulate(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& pose,
                       const NdtGaussConstants& k, NdtLookup lookup) {
  const GridGeometry& g = grid.geometry();
  const int32_t* index = grid.cellIndex().data();
  const NdtCell* cells = grid.cells().data();
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  const double inv = 1.0 / g.resolution, ox = g.origin.x(), oy = g.origin.y();
  const double shift = lookup == NdtLookup::FourNearest ? 0.5 : 0.0;
  Accumulator acc;
  for (const Eigen::Vector2d& p : points) {
    const double a = c * p.x() - s * p.y(), b = s * p.x() + c * p.y();
    const double tx = a + pose.x(), ty = b + pose.y();
    const double u = (tx - ox) * inv - shift, v = (ty - oy) * inv - shift;
    if (!(u > -1.0 && v > -1.0 && u < g.cols && v < g.rows)) continue;
    const int col = int(std::floor(u)), row = int(std::floor(v));
    if (lookup == NdtLookup::ContainingCell) {
      if (col < 0 || row < 0) continue;
      const int32_t i = index[size_t(row) * size_t(g.cols) + size_t(col)];
      if (i >= 0) addTerm<D>(cells[i], tx, ty, a, b, k, acc);
      continue;
    }
    for (int r = row; r <= row + 1; ++r) {
      for (int cc = col; cc <= col + 1; ++cc) {
        if (!g.inside(cc, r)) continue;
        const int32_t i = index[size_t(r) * size_t(g.cols) + size_t(cc)];
        if (i >= 0) addTerm<D>(cells[i], tx, ty, a, b, k, acc);
      }
    }
  }
  return acc;
}

}  // namespace

NdtGaussConstants ndtGaussConstants(double outlierRatio, double cellSize) {
  if (!(outlierRatio > 0.0 && outlierRatio < 1.0)) {
    throw Error("NDT score", "outlier ratio must be in (0, 1), got " + std::to_string(outlierRatio));
  }
  if (!(cellSize > 0.0) || !std::isfinite(cellSize)) throw Error("NDT score", "cell size must be positive");
  const double c1 = 10.0 * (1.0 - outlierRatio);
  const double c2 = outlierRatio / (cellSize * cellSize);
  const double d3 = -std::log(c2);
  NdtGaussConstants k;
  k.d1 = -std::log(c1 + c2) - d3;
  k.d2 = -2.0 * std::log((-std::log(c1 * std::exp(-0.5) + c2) - d3) / k.d1);
  return k;
}

NdtScore scoreNdt(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& pose,
                  const NdtScoreParams& params, NdtDerivatives derivatives) {
  const NdtGaussConstants k = ndtGaussConstants(params.outlierRatio, grid.cellSize());
  Accumulator acc;
  switch (derivatives) {
    case NdtDerivatives::None: acc = accumulate<NdtDerivatives::None>(grid, points, pose, k, params.lookup); break;
    case NdtDerivatives::Gradient:
      acc = accumulate<NdtDerivatives::Gradient>(grid, points, pose, k, params.lookup);
      break;
    case NdtDerivatives::GradientAndHessian:
      acc = accumulate<NdtDerivatives::GradientAndHessian>(grid, points, pose, k, params.lookup);
      break;
  }
  NdtScore result;
  result.score = acc.score;
  result.matched = acc.matched;
  result.gradient << acc.gx, acc.gy, acc.gt;
  result.hessian << acc.hxx, acc.hxy, acc.hxt,  //
      acc.hxy, acc.hyy, acc.hyt,                 //
      acc.hxt, acc.hyt, acc.htt;
  return result;
}

}  // namespace hdprior
