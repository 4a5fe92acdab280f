#include "engine/map/boundary_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "engine/map/drivable_raster.h"

namespace hdprior {
namespace {

constexpr float kFar = 1e9f;  // "no cell of the other kind on this line"

// Runs fn(begin, end) over [0, n) split into fixed contiguous chunks, one per thread; the
// chunks are independent, so the result does not depend on scheduling.
template <typename Fn>
void parallelChunks(int n, Fn fn) {
  const int threads = int(std::clamp<unsigned>(std::thread::hardware_concurrency(), 1u, 8u));
  if (threads == 1 || n < 64) return fn(0, n);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(fn, int(int64_t(n) * t / threads), int(int64_t(n) * (t + 1) / threads));
  fn(0, int(int64_t(n) / threads));
  for (std::thread& th : pool) th.join();
}

// One raster row as bytes (1 = drivable).
void rowBytes(const DrivableRaster& raster, int row, std::vector<uint8_t>& out) {
  std::fill(out.begin(), out.end(), 0);
  for (const DrivableRaster::Run& run : raster.runs(row)) std::fill(out.begin() + run.begin, out.begin() + run.end, 1);
}

// Pass 1, per column but swept row by row so memory is read in order: the distance in
// cells from each cell to the nearest cell of the other kind in the same column.
void columnDistances(const DrivableRaster& raster, int colBegin, int colEnd, float* values) {
  const GridGeometry& g = raster.geometry();
  const size_t n = size_t(colEnd - colBegin);
  std::vector<float> lastFilled(n, -kFar), lastEmpty(n, -kFar);
  std::vector<uint8_t> filled(size_t(g.cols));
  for (int r = 0; r < g.rows; ++r) {
    rowBytes(raster, r, filled);
    float* out = values + g.index(colBegin, r);
    for (size_t i = 0; i < n; ++i) {
      const bool f = filled[size_t(colBegin) + i];
      (f ? lastFilled[i] : lastEmpty[i]) = float(r);
      out[i] = float(r) - (f ? lastEmpty[i] : lastFilled[i]);
    }
  }
  std::fill(lastFilled.begin(), lastFilled.end(), 2 * kFar);
  std::fill(lastEmpty.begin(), lastEmpty.end(), 2 * kFar);
  for (int r = g.rows - 1; r >= 0; --r) {
    rowBytes(raster, r, filled);
    float* out = values + g.index(colBegin, r);
    for (size_t i = 0; i < n; ++i) {
      const bool f = filled[size_t(colBegin) + i];
      (f ? lastFilled[i] : lastEmpty[i]) = float(r);
      out[i] = std::min(out[i], (f ? lastEmpty[i] : lastFilled[i]) - float(r));
    }
  }
}

// The 1-D squared distance transform d(q) = min_p (q - p)^2 + f(p): lower envelope of parabolas.
struct Envelope {
  std::vector<int> v;
  std::vector<double> z, lifted;  // lifted[q] = f(q) + q^2, each parabola's constant part
  double intersection(int q, int p) const { return (lifted[size_t(q)] - lifted[size_t(p)]) / (2.0 * (q - p)); }
  void transform(const double* f, int n, double* d) {
    v.resize(size_t(n));
    z.resize(size_t(n) + 1);
    lifted.resize(size_t(n));
    for (int q = 0; q < n; ++q) lifted[size_t(q)] = f[q] + double(q) * q;
    int k = 0;
    v[0] = 0;
    z[0] = -std::numeric_limits<double>::infinity();
    z[1] = std::numeric_limits<double>::infinity();
    for (int q = 1; q < n; ++q) {
      double s = intersection(q, v[size_t(k)]);
      while (s <= z[size_t(k)]) s = intersection(q, v[size_t(--k)]);
      ++k;
      v[size_t(k)] = q;
      z[size_t(k)] = s;
      z[size_t(k) + 1] = std::numeric_limits<double>::infinity();
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
      while (z[size_t(k) + 1] < q) ++k;
      const int p = v[size_t(k)];
      d[q] = double(q - p) * (q - p) + f[p];
    }
  }
};

}  // namespace

BoundaryDistance BoundaryDistance::build(const DrivableRaster& raster) {
  BoundaryDistance sdf;
  const GridGeometry& g = raster.geometry();
  sdf.geometry_ = g;
  sdf.values_.resize(g.cellCount());
  float* values = sdf.values_.data();
  parallelChunks(g.cols, [&](int begin, int end) { columnDistances(raster, begin, end, values); });

  // Pass 2 along rows: for cells of each kind, the nearest cell of the other kind in 2-D.
  // A filled cell's column distance is its distance to an empty cell and vice versa; the
  // cells of the target kind themselves are the sites (f = 0).
  const double res = g.resolution;
  parallelChunks(g.rows, [&](int begin, int end) {
    const size_t n = static_cast<size_t>(g.cols);
    std::vector<double> toFilled(n), toEmpty(n), dFilled(n), dEmpty(n);
    std::vector<uint8_t> filled(n);
    Envelope envelope;
    for (int r = begin; r < end; ++r) {
      rowBytes(raster, r, filled);
      float* row = values + g.index(0, r);
      for (size_t c = 0; c < n; ++c) {
        const double column2 = double(row[c]) * row[c];
        toFilled[c] = filled[c] ? 0.0 : column2;
        toEmpty[c] = filled[c] ? column2 : 0.0;
      }
      envelope.transform(toFilled.data(), g.cols, dFilled.data());
      envelope.transform(toEmpty.data(), g.cols, dEmpty.data());
      for (size_t c = 0; c < n; ++c) {
        const double metres = std::sqrt(filled[c] ? dEmpty[c] : dFilled[c]) * res - 0.5 * res;
        row[c] = float(filled[c] ? -metres : metres);
      }
    }
  });
  return sdf;
}

double BoundaryDistance::distance(const Eigen::Vector2d& city) const {
  const GridGeometry& g = geometry_;
  const Eigen::Vector2d uv = g.toCell(city);
  if (!(uv.x() >= 0.0 && uv.y() >= 0.0 && uv.x() <= g.cols && uv.y() <= g.rows)) return NAN;
  const double u = std::clamp(uv.x() - 0.5, 0.0, double(g.cols - 1));
  const double v = std::clamp(uv.y() - 0.5, 0.0, double(g.rows - 1));
  const int c0 = std::min(int(u), g.cols - 2 < 0 ? 0 : g.cols - 2), r0 = std::min(int(v), g.rows - 2 < 0 ? 0 : g.rows - 2);
  const int c1 = std::min(c0 + 1, g.cols - 1), r1 = std::min(r0 + 1, g.rows - 1);
  const double fu = u - c0, fv = v - r0;
  return (1 - fv) * ((1 - fu) * at(c0, r0) + fu * at(c1, r0)) + fv * ((1 - fu) * at(c0, r1) + fu * at(c1, r1));
}

}  // namespace hdprior
