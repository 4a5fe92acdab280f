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

// One point-to-cell term and its derivatives (Magnusson 2009, eqs. 6.12-6.13, specialised to SE(2)).
// (a, b) is R(yaw) p, so dq/dx = (1, 0), dq/dy = (0, 1), dq/dyaw = (-b, a), d2q/dyaw2 = (-a, -b).
struct Term {
  double score = 0, gx = 0, gy = 0, gt = 0;
  double hxx = 0, hxy = 0, hxt = 0, hyy = 0, hyt = 0, htt = 0;
};

template <NdtDerivatives D>
inline Term cellTerm(const NdtCell& cell, double tx, double ty, double a, double b, const NdtGaussConstants& k) {
  Term t;
  const double qx = tx - cell.mean.x(), qy = ty - cell.mean.y();
  const double i00 = cell.information(0, 0), i01 = cell.information(0, 1), i11 = cell.information(1, 1);
  const double u0 = i00 * qx + i01 * qy, u1 = i01 * qx + i11 * qy;  // Sigma^-1 q
  const double e = std::exp(-0.5 * k.d2 * (qx * u0 + qy * u1));
  t.score = -k.d1 * e;
  if constexpr (D == NdtDerivatives::None) return t;
  const double f = k.d1 * k.d2 * e;
  const double gt = a * u1 - b * u0;  // q^T Sigma^-1 dq/dyaw
  t.gx = f * u0;
  t.gy = f * u1;
  t.gt = f * gt;
  if constexpr (D != NdtDerivatives::GradientAndHessian) return t;
  const double w0 = i01 * a - i00 * b, w1 = i11 * a - i01 * b;  // Sigma^-1 dq/dyaw
  const double d2 = k.d2;
  t.hxx = f * (i00 - d2 * u0 * u0);
  t.hxy = f * (i01 - d2 * u0 * u1);
  t.hyy = f * (i11 - d2 * u1 * u1);
  t.hxt = f * (w0 - d2 * u0 * gt);
  t.hyt = f * (w1 - d2 * u1 * gt);
  t.htt = f * ((a * w1 - b * w0) - (a * u0 + b * u1) - d2 * gt * gt);
  return t;
}

inline void add(Accumulator& acc, const Term& t) {
  acc.score += t.score;
  acc.gx += t.gx, acc.gy += t.gy, acc.gt += t.gt;
  acc.hxx += t.hxx, acc.hxy += t.hxy, acc.hxt += t.hxt, acc.hyy += t.hyy, acc.hyt += t.hyt, acc.htt += t.htt;
  ++acc.matched;
}

// The bilinear weight W(tx, ty) = wx(tx) wy(ty) of one of the 2 x 2 cells around a point, as a function
// of the pose: its value, gradient (x, y, yaw) and Hessian. wx and wy are linear in tx and ty with slopes
// dwx, dwy, so only the mixed second derivative c = dwx dwy of W in (tx, ty) is not zero.
struct Weight {
  double w = 1, gx = 0, gy = 0, gt = 0;
  double hxy = 0, hxt = 0, hyt = 0, htt = 0;
};

inline Weight bilinearWeight(double wx, double wy, double dwx, double dwy, double a, double b) {
  Weight W;
  W.w = wx * wy;
  const double Wx = dwx * wy, Wy = wx * dwy, c = dwx * dwy;  // dW/dtx, dW/dty, d2W/dtx dty
  W.gx = Wx;
  W.gy = Wy;
  W.gt = -b * Wx + a * Wy;  // dtx/dyaw = -b, dty/dyaw = a
  W.hxy = c;
  W.hxt = c * a;
  W.hyt = -c * b;
  W.htt = -a * Wx - b * Wy - 2.0 * a * b * c;
  return W;
}

// W * term: the product rule (the weight's own Hessian is zero in xx and yy).
inline Term weighted(const Term& t, const Weight& W) {
  Term r;
  r.score = W.w * t.score;
  r.gx = W.w * t.gx + t.score * W.gx;
  r.gy = W.w * t.gy + t.score * W.gy;
  r.gt = W.w * t.gt + t.score * W.gt;
  r.hxx = W.w * t.hxx + 2.0 * W.gx * t.gx;
  r.hyy = W.w * t.hyy + 2.0 * W.gy * t.gy;
  r.htt = W.w * t.htt + 2.0 * W.gt * t.gt + t.score * W.htt;
  r.hxy = W.w * t.hxy + W.gx * t.gy + W.gy * t.gx + t.score * W.hxy;
  r.hxt = W.w * t.hxt + W.gx * t.gt + W.gt * t.gx + t.score * W.hxt;
  r.hyt = W.w * t.hyt + W.gy * t.gt + W.gt * t.gy + t.score * W.hyt;
  return r;
}

template <NdtDerivatives D>
Accumulator accumulate(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& pose,
                       const NdtGaussConstants& k, NdtLookup lookup) {
  const GridGeometry& g = grid.geometry();
  const int32_t* index = grid.cellIndex().data();
  const NdtCell* cells = grid.cells().data();
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  const double inv = 1.0 / g.resolution, ox = g.origin.x(), oy = g.origin.y();
  const double shift = lookup == NdtLookup::ContainingCell ? 0.0 : 0.5;
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
      if (i >= 0) add(acc, cellTerm<D>(cells[i], tx, ty, a, b, k));
      continue;
    }
    const double fu = u - col, fv = v - row;
    for (int r = row; r <= row + 1; ++r) {
      for (int cc = col; cc <= col + 1; ++cc) {
        if (!g.inside(cc, r)) continue;
        const int32_t i = index[size_t(r) * size_t(g.cols) + size_t(cc)];
        if (i < 0) continue;
        const Term t = cellTerm<D>(cells[i], tx, ty, a, b, k);
        if (lookup == NdtLookup::FourNearest) {
          add(acc, t);
          continue;
        }
        const double wx = cc == col ? 1.0 - fu : fu, wy = r == row ? 1.0 - fv : fv;
        const double dwx = (cc == col ? -inv : inv), dwy = (r == row ? -inv : inv);
        add(acc, weighted(t, bilinearWeight(wx, wy, dwx, dwy, a, b)));
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
