#include "engine/map/drivable_raster.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/error.h"

namespace hdprior {
namespace {

// A span of drivable cells of one polygon in one row.
struct RowSpan {
  int32_t row, begin, end;
};

void checkOptions(const DrivableRasterOptions& o, const std::string& source) {
  if (!std::isfinite(o.resolution) || o.resolution < 1e-3 || o.resolution > 100.0) {
    throw Error(source, "raster resolution must be between 0.001 and 100 m, got " + std::to_string(o.resolution));
  }
  if (!std::isfinite(o.margin) || o.margin < o.resolution) {
    throw Error(source, "raster margin must be at least one cell (" + std::to_string(o.resolution) + " m)");
  }
}

double shoelaceArea(const Polyline3& ring) {
  double twice = 0.0;
  for (size_t i = 0, n = ring.size(); i < n; ++i) {
    const Eigen::Vector3d& p = ring[i];
    const Eigen::Vector3d& q = ring[(i + 1) % n];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

void checkPolygons(const VectorMap& map, const std::string& source) {
  if (map.drivableAreas.empty()) throw Error(source, "map has no drivable areas");
  for (const DrivableArea& a : map.drivableAreas) {
    const std::string name = "drivable area " + std::to_string(a.id);
    if (a.areaBoundary.size() < 3) {
      throw Error(source, name + " has " + std::to_string(a.areaBoundary.size()) +
                              " vertices; a polygon needs at least 3");
    }
    for (const Eigen::Vector3d& p : a.areaBoundary) {
      if (!p.allFinite()) throw Error(source, name + " has a non-finite vertex");
    }
    if (std::abs(shoelaceArea(a.areaBoundary)) < 1e-9) {
      throw Error(source, name + " has zero area (its vertices are collinear)");
    }
  }
}

GridGeometry gridOver(const VectorMap& map, const DrivableRasterOptions& o, const std::string& source) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = Eigen::Vector2d::Constant(-INFINITY);
  for (const DrivableArea& a : map.drivableAreas) {
    for (const Eigen::Vector3d& p : a.areaBoundary) {
      lo = lo.cwiseMin(p.head<2>());
      hi = hi.cwiseMax(p.head<2>());
    }
  }
  lo.array() -= o.margin;
  hi.array() += o.margin;
  if (o.window) {
    lo = lo.cwiseMax(o.window->min());
    hi = hi.cwiseMin(o.window->max()).cwiseMax(lo);  // no overlap: a strip one cell wide at lo
  }
  const Eigen::Vector2d first = (lo / o.resolution).array().floor();
  const Eigen::Vector2d last = ((hi / o.resolution).array().ceil()).cwiseMax(first.array() + 1.0);
  const Eigen::Vector2d size = last - first;
  const double cells = size.x() * size.y();
  if (!(cells <= double(o.maxCells)) || size.maxCoeff() > 1e9) {
    throw Error(source, "drivable area extent " + std::to_string(hi.x() - lo.x() - 2 * o.margin) + " x " +
                            std::to_string(hi.y() - lo.y() - 2 * o.margin) + " m gives " + std::to_string(cells) +
                            " cells at " + std::to_string(o.resolution) + " m, more than the limit of " +
                            std::to_string(o.maxCells));
  }
  GridGeometry g;
  g.resolution = o.resolution;
  g.origin = first * o.resolution;
  g.cols = int(size.x());
  g.rows = int(size.y());
  return g;
}

double centreX(const GridGeometry& g, int col) { return g.origin.x() + (col + 0.5) * g.resolution; }
double centreY(const GridGeometry& g, int row) { return g.origin.y() + (row + 0.5) * g.resolution; }

// Smallest index i in [0, n] whose cell centre is >= v (centre(i) is increasing in i).
template <typename Centre>
int firstCentreAtOrAbove(double v, double origin, double res, int n, Centre centre) {
  double guess = std::ceil((v - origin) / res - 0.5);
  int i = int(std::clamp(guess, 0.0, double(n)));
  while (i < n && centre(i) < v) ++i;
  while (i > 0 && centre(i - 1) >= v) --i;
  return i;
}

// Even-odd scanline fill of one polygon at the cell-centre rows: an edge (p, q) crosses row
// y when (p.y <= y) != (q.y <= y), exactly the crossing rule of point-in-polygon tests.
void polygonSpans(const Polyline3& ring, const GridGeometry& g, std::vector<RowSpan>& out) {
  std::vector<std::pair<int32_t, double>> crossings;  // (row, x)
  const auto cy = [&](int r) { return centreY(g, r); };
  const auto cx = [&](int c) { return centreX(g, c); };
  for (size_t i = 0, n = ring.size(); i < n; ++i) {
    const Eigen::Vector3d& p = ring[i];
    const Eigen::Vector3d& q = ring[(i + 1) % n];
    if (p.y() == q.y()) continue;
    const double ymin = std::min(p.y(), q.y()), ymax = std::max(p.y(), q.y());
    const int r0 = firstCentreAtOrAbove(ymin, g.origin.y(), g.resolution, g.rows, cy);
    const int r1 = firstCentreAtOrAbove(ymax, g.origin.y(), g.resolution, g.rows, cy);
    const double slope = (q.x() - p.x()) / (q.y() - p.y());
    for (int r = r0; r < r1; ++r) crossings.emplace_back(r, p.x() + (cy(r) - p.y()) * slope);
  }
  std::sort(crossings.begin(), crossings.end());
  for (size_t i = 0; i + 1 < crossings.size(); i += 2) {
    const int row = crossings[i].first;
    if (crossings[i + 1].first != row) {  // cannot happen for a closed ring; stay robust
      --i;
      continue;
    }
    const int b = firstCentreAtOrAbove(crossings[i].second, g.origin.x(), g.resolution, g.cols, cx);
    const int e = firstCentreAtOrAbove(crossings[i + 1].second, g.origin.x(), g.resolution, g.cols, cx);
    if (b < e) out.push_back({row, b, e});
  }
}

}  // namespace

DrivableRaster DrivableRaster::build(const VectorMap& map, const DrivableRasterOptions& options,
                                     const std::string& source) {
  checkOptions(options, source);
  checkPolygons(map, source);
  DrivableRaster r;
  r.geometry_ = gridOver(map, options, source);
  const GridGeometry& g = r.geometry_;

  std::vector<RowSpan> spans;
  for (const DrivableArea& a : map.drivableAreas) polygonSpans(a.areaBoundary, g, spans);
  std::sort(spans.begin(), spans.end(), [](const RowSpan& a, const RowSpan& b) {
    return a.row != b.row ? a.row < b.row : a.begin < b.begin;
  });

  // Union: merge overlapping or touching spans of the same row into runs.
  r.rowStart_.assign(size_t(g.rows) + 1, 0);
  r.wordsPerRow_ = (size_t(g.cols) + 63) / 64;
  r.bits_.assign(r.wordsPerRow_ * size_t(g.rows), 0);
  for (size_t i = 0; i < spans.size();) {
    const int row = spans[i].row;
    Run run{spans[i].begin, spans[i].end};
    for (++i; i < spans.size() && spans[i].row == row && spans[i].begin <= run.end; ++i) {
      run.end = std::max(run.end, spans[i].end);
    }
    r.runs_.push_back(run);
    r.rowStart_[size_t(row) + 1] = r.runs_.size();
    r.setBits(row, run);
    r.drivableCells_ += size_t(run.end - run.begin);
  }
  if (r.drivableCells_ == 0) {
    throw Error(source, "the drivable areas cover no cell centre at " + std::to_string(g.resolution) + " m resolution");
  }
  for (size_t row = 1; row < r.rowStart_.size(); ++row) r.rowStart_[row] = std::max(r.rowStart_[row], r.rowStart_[row - 1]);

  r.boundaryPoints_ = r.traceBoundary(map);
  return r;
}

void DrivableRaster::setBits(int row, const Run& run) {
  uint64_t* words = bits_.data() + size_t(row) * wordsPerRow_;
  for (int col = run.begin; col < run.end;) {
    const int bit = col & 63, n = std::min(64 - bit, run.end - col);
    const uint64_t ones = n == 64 ? ~uint64_t(0) : ((uint64_t(1) << n) - 1);
    words[col >> 6] |= ones << bit;
    col += n;
  }
}

bool DrivableRaster::contains(const Eigen::Vector2d& city) const {
  int col, row;
  return geometry_.cellOf(city, col, row) && drivable(col, row);
}

std::vector<uint8_t> DrivableRaster::cellBytes() const {
  std::vector<uint8_t> bytes(geometry_.cellCount(), 0);
  for (int row = 0; row < geometry_.rows; ++row) {
    for (const Run& run : runs(row)) {
      std::memset(bytes.data() + geometry_.index(run.begin, row), 1, size_t(run.end - run.begin));
    }
  }
  return bytes;
}

std::vector<Eigen::Vector2d> DrivableRaster::surfacePoints() const {
  std::vector<Eigen::Vector2d> points;
  points.reserve(drivableCells_);
  for (int row = 0; row < geometry_.rows; ++row) {
    for (const Run& run : runs(row)) {
      for (int col = run.begin; col < run.end; ++col) points.push_back(geometry_.cellCentre(col, row));
    }
  }
  return points;
}

// Samples every polygon edge each `resolution` metres and keeps the samples next to a
// non-drivable cell: edges shared by two polygons or lying inside another polygon are
// interior to the union and dropped. A sample in the same half-resolution cell as an earlier
// one (coinciding edges) is dropped; the points come sorted row by row.
std::vector<Eigen::Vector2d> DrivableRaster::traceBoundary(const VectorMap& map) const {
  const GridGeometry& g = geometry_;
  // Samples outside the raster (a window of the map: DrivableRasterOptions::window) are dropped.
  const auto nextToEmpty = [&](const Eigen::Vector2d& p) {
    int col, row;
    if (!g.cellOf(p, col, row)) return false;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (!drivable(col + dc, row + dr)) return true;
      }
    }
    return false;
  };
  struct Sample {
    int64_t key;  // the sample's cell on a grid of half the resolution, row-major
    Eigen::Vector2d point;
  };
  std::vector<Sample> samples;
  const double half = 0.5 * g.resolution;
  const int64_t halfCols = int64_t(g.cols) * 2 + 4;
  for (const DrivableArea& a : map.drivableAreas) {
    const Polyline3& ring = a.areaBoundary;
    for (size_t i = 0, n = ring.size(); i < n; ++i) {
      const Eigen::Vector2d p = ring[i].head<2>(), q = ring[(i + 1) % n].head<2>();
      const int count = std::max(1, int(std::ceil((q - p).norm() / g.resolution)));
      for (int k = 0; k < count; ++k) {
        const Eigen::Vector2d s = p + (q - p) * (double(k) / count);
        if (!nextToEmpty(s)) continue;
        const Eigen::Vector2d key = ((s - g.origin) / half).array().round();
        samples.push_back({int64_t(key.y()) * halfCols + int64_t(key.x()), s});
      }
    }
  }
  std::stable_sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.key < b.key; });
  std::vector<Eigen::Vector2d> points;
  points.reserve(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    if (i == 0 || samples[i].key != samples[i - 1].key) points.push_back(samples[i].point);
  }
  return points;
}

}  // namespace hdprior
