#include "engine/map/ndt_score.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
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

// The Double4 helpers are always inlined into the AVX2 function, so no call passes one by value
// across the ABI GCC warns about.
#pragma GCC diagnostic ignored "-Wpsabi"

// Four doubles in one AVX2 register (GCC's vector extension); plain double is the one-lane case.
typedef double Double4 __attribute__((vector_size(32)));
typedef int64_t Int4 __attribute__((vector_size(32)));

#define HDPRIOR_INLINE __attribute__((always_inline)) inline
HDPRIOR_INLINE double atLeast(double x, double low) { return x < low ? low : x; }
HDPRIOR_INLINE Double4 atLeast(Double4 x, double low) { return x < low ? Double4{low, low, low, low} : x; }
// 2^n for a double whose low mantissa bits hold the integer n (see expNonPositive).
HDPRIOR_INLINE double powerOfTwo(double kd) { return std::bit_cast<double>((std::bit_cast<uint64_t>(kd) + 1023) << 52); }
HDPRIOR_INLINE Double4 powerOfTwo(Double4 kd) { return (Double4)(((Int4)kd + 1023) << 52); }

// exp(x) for x <= 0 (below -700 as exp(-700)), to 1e-14 relative: Cody-Waite reduction by ln 2, a
// degree-11 Taylor polynomial and the power of two built in the exponent bits. Plain arithmetic, so
// it runs in SIMD lanes (libm's exp is a call per term, and most of the score's time).
template <typename V>
HDPRIOR_INLINE V expNonPositive(V x) {
  x = atLeast(x, -700.0);
  constexpr double shifter = 0x1.8p52;  // adding it rounds x / ln 2 to an integer in the low bits
  const V kd = x * 1.4426950408889634 + shifter;
  const V n = kd - shifter;
  const V r = (x - n * 0.693147180369123816490) - n * 1.90821492927058770002e-10;
  V p = r * (1.0 / 39916800.0) + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  return p * powerOfTwo(kd);
}

// Point-to-cell terms gathered for the evaluation in lanes: the offset q from the cell mean, the
// cell's information (i00, i01, i11) and the rotated point (a, b).
struct TermBlock {
  static constexpr size_t kCapacity = 1024;
  double qx[kCapacity], qy[kCapacity], i00[kCapacity], i01[kCapacity], i11[kCapacity], a[kCapacity], b[kCapacity];
  size_t size = 0;
};

// Running sums of cellTerm in lanes: score, gradient (x, y, yaw), Hessian (xx, xy, xt, yy, yt, tt).
template <typename V>
struct LaneSums {
  V v[10] = {};
};

template <NdtDerivatives D, typename V>
HDPRIOR_INLINE void addTerm(const V& qx, const V& qy, const V& i00, const V& i01, const V& i11, const V& a, const V& b,
                            double d1, double d2, LaneSums<V>& sums) {
  V* s = sums.v;
  const V u0 = i00 * qx + i01 * qy, u1 = i01 * qx + i11 * qy;
  const V e = expNonPositive<V>(-0.5 * d2 * (qx * u0 + qy * u1));
  s[0] += -d1 * e;
  if constexpr (D == NdtDerivatives::None) return;
  const V f = d1 * d2 * e;
  const V g = a * u1 - b * u0;
  s[1] += f * u0, s[2] += f * u1, s[3] += f * g;
  if constexpr (D != NdtDerivatives::GradientAndHessian) return;
  const V w0 = i01 * a - i00 * b, w1 = i11 * a - i01 * b;
  s[4] += f * (i00 - d2 * u0 * u0);
  s[5] += f * (i01 - d2 * u0 * u1);
  s[6] += f * (w0 - d2 * u0 * g);
  s[7] += f * (i11 - d2 * u1 * u1);
  s[8] += f * (w1 - d2 * u1 * g);
  s[9] += f * ((a * w1 - b * w0) - (a * u0 + b * u1) - d2 * g * g);
}

template <NdtDerivatives D>
HDPRIOR_INLINE void addScalarTerms(const TermBlock& t, size_t from, double d1, double d2, LaneSums<double>& sums) {
  for (size_t j = from; j < t.size; ++j) addTerm<D>(t.qx[j], t.qy[j], t.i00[j], t.i01[j], t.i11[j], t.a[j], t.b[j], d1, d2, sums);
}

HDPRIOR_INLINE Double4 load4(const double* p) {
  Double4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Four terms at a time on CPUs with AVX2 and FMA, the rest one by one.
template <NdtDerivatives D>
__attribute__((target("avx2,fma"))) LaneSums<double> sumTermsAvx2(const TermBlock& t, double d1, double d2) {
  LaneSums<Double4> lanes;
  size_t j = 0;
  for (; j + 4 <= t.size; j += 4) {
    addTerm<D>(load4(t.qx + j), load4(t.qy + j), load4(t.i00 + j), load4(t.i01 + j), load4(t.i11 + j), load4(t.a + j),
               load4(t.b + j), d1, d2, lanes);
  }
  LaneSums<double> sums;
  for (int i = 0; i < 10; ++i) sums.v[i] = (lanes.v[i][0] + lanes.v[i][1]) + (lanes.v[i][2] + lanes.v[i][3]);
  addScalarTerms<D>(t, j, d1, d2, sums);
  return sums;
}

template <NdtDerivatives D>
void addTerms(const TermBlock& t, const NdtGaussConstants& k, Accumulator& acc) {
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  LaneSums<double> sums;
  if (avx2) {
    sums = sumTermsAvx2<D>(t, k.d1, k.d2);
  } else {
    addScalarTerms<D>(t, 0, k.d1, k.d2, sums);
  }
  const double* s = sums.v;
  acc.score += s[0];
  acc.gx += s[1], acc.gy += s[2], acc.gt += s[3];
  acc.hxx += s[4], acc.hxy += s[5], acc.hxt += s[6], acc.hyy += s[7], acc.hyt += s[8], acc.htt += s[9];
  acc.matched += t.size;
}

// A point placed on the grid by the pose: (a, b) = R(yaw) p, (tx, ty) its map position.
struct PlacedPoint {
  double a, b, tx, ty;
};

// Calls visit(point, cell index) for each valid cell of the 2 x 2 whose centres surround a point.
template <typename Visit>
HDPRIOR_INLINE void forEachCell(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& pose,
                                Visit&& visit) {
  const GridGeometry& g = grid.geometry();
  const int32_t* index = grid.cellIndex().data();
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  const double inv = 1.0 / g.resolution, ox = g.origin.x(), oy = g.origin.y();
  for (const Eigen::Vector2d& p : points) {
    PlacedPoint q{c * p.x() - s * p.y(), s * p.x() + c * p.y(), 0.0, 0.0};
    q.tx = q.a + pose.x(), q.ty = q.b + pose.y();
    const double u = (q.tx - ox) * inv - 0.5, v = (q.ty - oy) * inv - 0.5;
    if (!(u > -1.0 && v > -1.0 && u < g.cols && v < g.rows)) continue;
    const int col = int(std::floor(u)), row = int(std::floor(v));
    for (int dr = 0; dr <= 1; ++dr) {
      for (int dc = 0; dc <= 1; ++dc) {
        if (!g.inside(col + dc, row + dr)) continue;
        const int32_t i = index[size_t(row + dr) * size_t(g.cols) + size_t(col + dc)];
        if (i >= 0) visit(q, i);
      }
    }
  }
}

// The terms of the four nearest cells, gathered in blocks and summed in lanes.
template <NdtDerivatives D>
Accumulator accumulate(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& pose,
                       const NdtGaussConstants& k) {
  const NdtCell* cells = grid.cells().data();
  Accumulator acc;
  auto block = std::make_unique<TermBlock>();
  TermBlock& t = *block;
  forEachCell(grid, points, pose, [&](const PlacedPoint& q, int32_t i) {
    const NdtCell& cell = cells[i];
    t.qx[t.size] = q.tx - cell.mean.x(), t.qy[t.size] = q.ty - cell.mean.y();
    t.i00[t.size] = cell.information(0, 0), t.i01[t.size] = cell.information(0, 1), t.i11[t.size] = cell.information(1, 1);
    t.a[t.size] = q.a, t.b[t.size] = q.b;
    if (++t.size == TermBlock::kCapacity) {
      addTerms<D>(t, k, acc);
      t.size = 0;
    }
  });
  if (t.size > 0) addTerms<D>(t, k, acc);
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
    case NdtDerivatives::None: acc = accumulate<NdtDerivatives::None>(grid, points, pose, k); break;
    case NdtDerivatives::Gradient: acc = accumulate<NdtDerivatives::Gradient>(grid, points, pose, k); break;
    case NdtDerivatives::GradientAndHessian: acc = accumulate<NdtDerivatives::GradientAndHessian>(grid, points, pose, k); break;
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
