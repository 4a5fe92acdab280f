#include "engine/sim/road_paint.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>

#include "engine/io/vector_map.h"
#include "engine/sim/splitmix.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;
using Mark = RoadPaint::Mark;

// The lines of a mark type, left to right: dashed or not. Empty when nothing is painted.
std::vector<bool> linesOf(const std::string& type) {
  const auto starts = [&](const char* prefix) { return type.rfind(prefix, 0) == 0; };
  if (starts("DOUBLE_SOLID")) return {false, false};
  if (starts("DOUBLE_DASH")) return {true, true};
  if (starts("DASH_SOLID")) return {true, false};
  if (starts("SOLID_DASH")) return {false, true};
  if (starts("DASHED")) return {true};
  if (starts("SOLID")) return {false};
  return {};
}

void addLine(const Polyline3& line, const std::string& type, const PaintOptions& options, std::vector<Mark>& marks) {
  const std::vector<bool> lines = linesOf(type);
  if (lines.empty()) return;
  const uint8_t reflectivity = type.find("WHITE") != std::string::npos ? options.white : options.yellow;
  const double w = options.lineWidth, spacing = w + options.doubleLineGap;
  double s = 0.0;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec2 a = line[i].head<2>(), d = line[i + 1].head<2>() - a;
    const double length = d.norm();
    if (length < 1e-6) continue;
    for (size_t k = 0; k < lines.size(); ++k) {
      // Left of the line is positive across; the lines of a pair sit either side of it.
      const double centre = lines.size() == 1 ? 0.0 : (k == 0 ? 0.5 : -0.5) * spacing;
      Mark m{a, d / length, length, centre - 0.5 * w, centre + 0.5 * w, s, 0.0, 0.0, reflectivity};
      if (lines[k]) {
        m.on = options.dashLength;
        m.period = options.dashLength + options.dashGap;
      }
      marks.push_back(m);
    }
    s += length;
  }
}

void addCrossing(const PedestrianCrossing& c, const PaintOptions& options, std::vector<Mark>& marks) {
  // Stripes along the crossing's edges' direction, repeated along edge1, spanning to edge2.
  const Vec2 a = c.edge1.front().head<2>(), b = c.edge1.back().head<2>();
  const double length = (b - a).norm();
  if (length < 1e-6) return;
  const Vec2 along = (b - a) / length, across(-along.y(), along.x());
  double lo = 0.0, hi = 0.0;
  for (const Eigen::Vector3d& p : c.edge2) {
    const double v = (p.head<2>() - a).dot(across);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  marks.push_back({a, along, length, lo, hi, 0.0, options.stripeWidth, options.stripeWidth + options.stripeGap,
                    options.white});
}

bool covers(const Mark& m, const Vec2& p) {
  const Vec2 d = p - m.origin;
  const double a = d.dot(m.along), c = m.along.x() * d.y() - m.along.y() * d.x();
  if (a < 0.0 || a > m.length || c < m.acrossMin || c > m.acrossMax) return false;
  return m.period <= 0.0 || std::fmod(m.phase + a, m.period) < m.on;
}

}  // namespace

RoadPaint::RoadPaint(const VectorMap& map, const Vec2& lo, const Vec2& hi, const PaintOptions& options)
    : options_(options) {
  std::set<LaneLineKey> painted;
  const auto near = [&](const Polyline3& line) {
    return std::any_of(line.begin(), line.end(), [&](const Eigen::Vector3d& p) {
      return (p.head<2>().array() >= lo.array() - 50.0).all() && (p.head<2>().array() <= hi.array() + 50.0).all();
    });
  };
  for (const LaneSegment& lane : map.laneSegments)
    for (const auto& [line, type] : {std::pair(&lane.leftLaneBoundary, &lane.leftLaneMarkType),
                                     std::pair(&lane.rightLaneBoundary, &lane.rightLaneMarkType)})
      if (line->size() >= 2 && !linesOf(*type).empty() && near(*line) && painted.insert(laneLineKey(*line)).second)
        addLine(*line, *type, options_, marks_);
  for (const PedestrianCrossing& c : map.pedestrianCrossings)
    if (c.edge1.size() >= 2 && c.edge2.size() >= 2 && near(c.edge1)) addCrossing(c, options_, marks_);
  index(lo, hi);
}

void RoadPaint::index(const Vec2& lo, const Vec2& hi) {
  const double cell = options_.cellSize;
  grid_.resolution = cell;
  grid_.origin = (lo / cell).array().floor() * cell;
  grid_.cols = std::max(1, int(std::ceil((hi.x() - grid_.origin.x()) / cell)) + 1);
  grid_.rows = std::max(1, int(std::ceil((hi.y() - grid_.origin.y()) / cell)) + 1);
  const auto forCells = [&](const Mark& m, auto&& fn) {
    const Vec2 across(-m.along.y(), m.along.x());
    Vec2 a = m.origin + m.acrossMin * across, b = a;
    for (const Vec2& p : {Vec2(m.origin + m.acrossMax * across), Vec2(m.origin + m.length * m.along + m.acrossMin * across),
                          Vec2(m.origin + m.length * m.along + m.acrossMax * across)})
      a = a.cwiseMin(p), b = b.cwiseMax(p);
    const Vec2 ca = grid_.toCell(a), cb = grid_.toCell(b);
    for (int r = std::max(0, int(std::floor(ca.y()))); r <= std::min(grid_.rows - 1, int(std::floor(cb.y()))); ++r)
      for (int c = std::max(0, int(std::floor(ca.x()))); c <= std::min(grid_.cols - 1, int(std::floor(cb.x()))); ++c)
        fn(grid_.index(c, r));
  };
  cellStart_.assign(grid_.cellCount() + 1, 0);
  for (const Mark& m : marks_) forCells(m, [&](size_t i) { ++cellStart_[i + 1]; });
  for (size_t i = 1; i < cellStart_.size(); ++i) cellStart_[i] += cellStart_[i - 1];
  items_.assign(cellStart_.back(), 0);
  std::vector<uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (size_t k = 0; k < marks_.size(); ++k) forCells(marks_[k], [&](size_t i) { items_[fill[i]++] = uint32_t(k); });
}

uint8_t RoadPaint::reflectivityAt(const Vec2& p) const {
  int col = 0, row = 0;
  if (marks_.empty() || !grid_.cellOf(p, col, row)) return 0;
  const size_t i = grid_.index(col, row);
  for (uint32_t k = cellStart_[i]; k < cellStart_[i + 1]; ++k)
    if (covers(marks_[items_[k]], p))
      return options_.wear > 0.0 && cellValue(p.x(), p.y(), 0.25, options_.wearSeed) < options_.wear ? 0 : marks_[items_[k]].reflectivity;
  return 0;
}

}  // namespace hdprior
