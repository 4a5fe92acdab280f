#include "engine/sim/town_generator.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "engine/error.h"
#include "engine/io/float16.h"
#include "engine/map/drivable_raster.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

Vec2 perp(const Vec2& v) { return {-v.y(), v.x()}; }  // 90 degrees to the left

// A street's centre curve, parameterised by arc length through a dense lookup table.
class StreetCurve {
 public:
  StreetCurve(const Vec2& a, const Vec2& control, const Vec2& b) : a_(a), c_(control), b_(b) {
    constexpr int kSamples = 512;
    arc_.resize(kSamples + 1, 0.0);
    Vec2 prev = a_;
    for (int i = 1; i <= kSamples; ++i) {
      const Vec2 p = at(double(i) / kSamples);
      arc_[size_t(i)] = arc_[size_t(i) - 1] + (p - prev).norm();
      prev = p;
    }
  }
  double length() const { return arc_.back(); }
  // Point and unit tangent at arc length s.
  Vec2 point(double s) const { return at(param(s)); }
  Vec2 tangent(double s) const {
    const double t = param(s);
    return (2.0 * (1.0 - t) * (c_ - a_) + 2.0 * t * (b_ - c_)).normalized();
  }

 private:
  Vec2 at(double t) const { return (1.0 - t) * (1.0 - t) * a_ + 2.0 * t * (1.0 - t) * c_ + t * t * b_; }
  double param(double s) const {
    const auto it = std::lower_bound(arc_.begin(), arc_.end(), s);
    if (it == arc_.begin()) return 0.0;
    if (it == arc_.end()) return 1.0;
    const size_t i = size_t(it - arc_.begin());
    const double f = (s - arc_[i - 1]) / std::max(1e-12, arc_[i] - arc_[i - 1]);
    return (double(i - 1) + f) / double(arc_.size() - 1);
  }
  Vec2 a_, c_, b_;
  std::vector<double> arc_;
};

// One lane of a street, as built before its links are known.
struct LaneEnds {
  size_t lane = 0;  // index into the lane list
  Vec2 leftStart, rightStart, leftEnd, rightEnd, startDir, endDir;
};

struct Builder {
  const TownOptions& options;
  TownMap& town;
  std::vector<StreetCurve> curves;
  std::vector<double> nodeRadius;  // the largest armRadius at each node
  // Distance from the node to where street s's road ends: [s][0] at `from`, [s][1] at `to`.
  // Clear of the widest other street there, so narrow streets reach into wide ones.
  std::vector<std::array<double, 2>> armRadius;
  // lanes[street][direction 0 = from->to, 1 = to->from][i, 0 = innermost]
  std::vector<std::array<std::vector<LaneEnds>, 2>> streetLanes;

  Eigen::Vector3d lift(const Vec2& p) const { return {p.x(), p.y(), town.terrain.height(p)}; }
  Polyline3 lift(const std::vector<Vec2>& line) const {
    Polyline3 out;
    out.reserve(line.size());
    for (const Vec2& p : line) out.push_back(lift(p));
    return out;
  }
};

void check(bool ok, const std::string& what) {
  if (!ok) throw Error("town options", what);
}

// Arc-length stations from s0 to s1, at most `spacing` apart (both ends included).
std::vector<double> stations(double s0, double s1, double spacing) {
  const int n = std::max(1, int(std::ceil((s1 - s0) / spacing)));
  std::vector<double> out;
  for (int i = 0; i <= n; ++i) out.push_back(s0 + (s1 - s0) * double(i) / n);
  return out;
}

// Cubic Bezier from p0 leaving along d0 to p3 arriving along d1, sampled every ~2 m.
std::vector<Vec2> connectorCurve(const Vec2& p0, const Vec2& d0, const Vec2& p3, const Vec2& d1) {
  const double k = 0.39 * (p3 - p0).norm();
  const Vec2 p1 = p0 + k * d0, p2 = p3 - k * d1;
  const int n = std::max(4, int(std::ceil((p3 - p0).norm() / 2.0)));
  std::vector<Vec2> out;
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n, u = 1.0 - t;
    out.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  }
  return out;
}

std::vector<Vec2> convexHull(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Vec2> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;  // counter-clockwise
}

// The street network: jittered grid, corridor loops, removed and curved streets, widths.
void buildNetwork(const TownOptions& o, std::mt19937_64& rng, TownMap& town) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto nodeAt = [&](int c, int r) { return r * o.gridCols + c; };
  for (int r = 0; r < o.gridRows; ++r) {
    for (int c = 0; c < o.gridCols; ++c) {
      const Vec2 jitter(o.jitter * (2 * unit(rng) - 1), o.jitter * (2 * unit(rng) - 1));
      town.nodes.push_back({Vec2(c * o.blockSize, r * o.blockSize) + jitter, 0});
    }
  }
  // One width per grid line (rows, then columns, then corridors); the extremes always occur.
  const int lines = o.gridRows + o.gridCols + o.corridors;
  std::vector<double> widths;
  for (int i = 0; i < lines; ++i) {
    widths.push_back(i == 0 ? o.minRoadWidth
                     : i == 1 ? o.maxRoadWidth
                              : o.minRoadWidth + (o.maxRoadWidth - o.minRoadWidth) * unit(rng));
  }
  std::shuffle(widths.begin(), widths.end(), rng);
  const auto addStreet = [&](int a, int b, double width, bool corridor) {
    TownStreet s;
    s.from = a;
    s.to = b;
    s.width = std::round(width * 2.0) / 2.0;
    s.lanesPerDirection = s.width >= o.threeLaneWidth ? 3 : s.width >= o.twoLaneWidth ? 2 : 1;
    s.corridor = corridor;
    town.streets.push_back(s);
  };
  for (int r = 0; r < o.gridRows; ++r)
    for (int c = 0; c + 1 < o.gridCols; ++c) addStreet(nodeAt(c, r), nodeAt(c + 1, r), widths[size_t(r)], false);
  for (int c = 0; c < o.gridCols; ++c)
    for (int r = 0; r + 1 < o.gridRows; ++r)
      addStreet(nodeAt(c, r), nodeAt(c, r + 1), widths[size_t(o.gridRows + c)], false);

  // Remove inner streets whose ends keep at least three streets (X becomes T).
  std::vector<int> degree(town.nodes.size(), 0);
  for (const TownStreet& s : town.streets) ++degree[size_t(s.from)], ++degree[size_t(s.to)];
  std::vector<size_t> order(town.streets.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  const size_t toRemove = size_t(std::round(o.removedEdgeFraction * double(town.streets.size())));
  std::vector<bool> removed(town.streets.size(), false);
  size_t removedCount = 0;
  for (size_t i : order) {
    if (removedCount >= toRemove) break;
    const TownStreet& s = town.streets[i];
    if (degree[size_t(s.from)] >= 4 && degree[size_t(s.to)] >= 4) {
      removed[i] = true;
      --degree[size_t(s.from)], --degree[size_t(s.to)];
      ++removedCount;
    }
  }
  std::vector<TownStreet> kept;
  for (size_t i = 0; i < town.streets.size(); ++i)
    if (!removed[i]) kept.push_back(town.streets[i]);
  town.streets = std::move(kept);

  // Corridor loops: from two junctions of the east (then north) edge out and back.
  for (int k = 0; k < o.corridors; ++k) {
    const bool east = k % 2 == 0;
    const int span = std::max(1, std::min(2, (east ? o.gridRows : o.gridCols) - 1));
    const int first = ((east ? o.gridRows : o.gridCols) - 1 - span) / 2;
    const int a = east ? nodeAt(o.gridCols - 1, first) : nodeAt(first, o.gridRows - 1);
    const int b = east ? nodeAt(o.gridCols - 1, first + span) : nodeAt(first + span, o.gridRows - 1);
    const Vec2 out = east ? Vec2(o.corridorLength, 0) : Vec2(0, o.corridorLength);
    const int ca = int(town.nodes.size()), cb = ca + 1;
    town.nodes.push_back({town.nodes[size_t(a)].position + out, 0});
    town.nodes.push_back({town.nodes[size_t(b)].position + out, 0});
    const double width = widths[size_t(o.gridRows + o.gridCols + k)];
    addStreet(a, ca, width, true);
    addStreet(ca, cb, width, true);
    addStreet(cb, b, width, true);
  }

  // Bend some streets (not the corridors) into quadratic Bezier curves.
  for (TownStreet& s : town.streets) {
    const Vec2 a = town.nodes[size_t(s.from)].position, b = town.nodes[size_t(s.to)].position;
    s.control = 0.5 * (a + b);
    if (!s.corridor && unit(rng) < o.curvedEdgeFraction) {
      const double offset = (unit(rng) < 0.5 ? -1.0 : 1.0) * (0.08 + 0.05 * unit(rng)) * (b - a).norm();
      s.control += offset * perp((b - a).normalized());
      s.curved = true;
    }
  }
  for (TownNode& n : town.nodes) n.degree = 0;
  for (const TownStreet& s : town.streets) ++town.nodes[size_t(s.from)].degree, ++town.nodes[size_t(s.to)].degree;
}

// Road polygons and the lanes along each street.
void buildStreets(Builder& b) {
  TownMap& town = b.town;
  VectorMap& map = town.vectorMap;
  b.nodeRadius.assign(town.nodes.size(), 0.0);
  b.armRadius.assign(town.streets.size(), {0.0, 0.0});
  for (size_t si = 0; si < town.streets.size(); ++si) {
    const TownStreet& s = town.streets[si];
    b.curves.emplace_back(town.nodes[size_t(s.from)].position, s.control, town.nodes[size_t(s.to)].position);
    for (int end = 0; end < 2; ++end) {
      const int node = end == 0 ? s.from : s.to;
      // Half width of the widest street crossing this arm at the node (arms within 45
      // degrees of straight ahead continue the street and do not count).
      const Vec2 at = town.nodes[size_t(node)].position;
      const Vec2 dir = (s.control - at).normalized();  // a Bezier leaves its end towards the control point
      double widest = 0.0;
      for (size_t oi = 0; oi < town.streets.size(); ++oi) {
        const TownStreet& o = town.streets[oi];
        if (oi == si || (o.from != node && o.to != node)) continue;
        if (dir.dot((o.control - at).normalized()) < -std::cos(std::numbers::pi / 4)) continue;
        widest = std::max(widest, 0.5 * o.width);
      }
      b.armRadius[si][size_t(end)] = 1.2 * widest + b.options.junctionMargin;
      b.nodeRadius[size_t(node)] = std::max(b.nodeRadius[size_t(node)], b.armRadius[si][size_t(end)]);
    }
  }
  b.streetLanes.resize(town.streets.size());
  for (size_t si = 0; si < town.streets.size(); ++si) {
    TownStreet& s = town.streets[si];
    const StreetCurve& curve = b.curves[si];
    s.length = curve.length();
    const double s0 = b.armRadius[si][0], s1 = s.length - b.armRadius[si][1];
    if (s1 - s0 < 10.0) throw Error("town options", "streets too short for their junctions");
    const std::vector<double> st = stations(s0, s1, 5.0);
    const double half = 0.5 * s.width;
    std::vector<Vec2> polygon;
    for (double x : st) polygon.push_back(curve.point(x) + half * perp(curve.tangent(x)));
    for (auto it = st.rbegin(); it != st.rend(); ++it) polygon.push_back(curve.point(*it) - half * perp(curve.tangent(*it)));
    map.drivableAreas.push_back({int64_t(map.drivableAreas.size()) + 1, b.lift(polygon)});

    const int n = s.lanesPerDirection;
    const double laneWidth = s.width / (2.0 * n);
    const auto offsetLine = [&](double offset, bool reverse) {
      std::vector<Vec2> line;
      for (double x : st) line.push_back(curve.point(x) + offset * perp(curve.tangent(x)));
      if (reverse) std::reverse(line.begin(), line.end());
      return line;
    };
    for (int dir = 0; dir < 2; ++dir) {
      for (int i = 0; i < n; ++i) {
        // Right-hand traffic: from->to lanes lie right of the centre line, to->from left of it.
        const double sign = dir == 0 ? -1.0 : 1.0;
        const std::vector<Vec2> left = offsetLine(sign * i * laneWidth, dir == 1);
        const std::vector<Vec2> right = offsetLine(sign * (i + 1) * laneWidth, dir == 1);
        LaneSegment lane;
        lane.id = int64_t(map.laneSegments.size()) + 1;
        lane.isIntersection = false;
        lane.laneType = "VEHICLE";
        lane.leftLaneBoundary = b.lift(left);
        lane.rightLaneBoundary = b.lift(right);
        lane.leftLaneMarkType = i == 0 ? "DOUBLE_SOLID_YELLOW" : "DASHED_WHITE";
        lane.rightLaneMarkType = i + 1 == n ? "SOLID_WHITE" : "DASHED_WHITE";
        LaneEnds ends;
        ends.lane = map.laneSegments.size();
        ends.leftStart = left.front(), ends.rightStart = right.front();
        ends.leftEnd = left.back(), ends.rightEnd = right.back();
        const double sStart = dir == 0 ? s0 : s1, sEnd = dir == 0 ? s1 : s0;
        ends.startDir = (dir == 0 ? 1.0 : -1.0) * curve.tangent(sStart);
        ends.endDir = (dir == 0 ? 1.0 : -1.0) * curve.tangent(sEnd);
        map.laneSegments.push_back(std::move(lane));
        b.streetLanes[si][size_t(dir)].push_back(ends);
      }
      // Neighbours within one direction: lane i's left neighbour is lane i - 1.
      auto& group = b.streetLanes[si][size_t(dir)];
      for (size_t i = 0; i < group.size(); ++i) {
        LaneSegment& l = map.laneSegments[group[i].lane];
        if (i > 0) l.leftNeighborId = map.laneSegments[group[i - 1].lane].id;
        if (i + 1 < group.size()) l.rightNeighborId = map.laneSegments[group[i + 1].lane].id;
      }
    }
  }
}

// Junction polygons, connector lanes through them and pedestrian crossings.
void buildJunctions(Builder& b) {
  TownMap& town = b.town;
  VectorMap& map = town.vectorMap;
  struct Arm {
    size_t street;
    bool atStart;  // the junction is the street's `from` node
    Vec2 end, out, side;  // road end centre, unit direction away from the node, left of `out`
    double half;
    double angle;
  };
  for (size_t node = 0; node < town.nodes.size(); ++node) {
    std::vector<Arm> arms;
    const double r = b.nodeRadius[node];
    for (size_t si = 0; si < town.streets.size(); ++si) {
      const TownStreet& s = town.streets[si];
      for (bool atStart : {true, false}) {
        if ((atStart ? s.from : s.to) != int(node)) continue;
        const StreetCurve& c = b.curves[si];
        const double x = atStart ? b.armRadius[si][0] : s.length - b.armRadius[si][1];
        Arm arm{si, atStart, c.point(x), (atStart ? 1.0 : -1.0) * c.tangent(x), Vec2::Zero(), 0.5 * s.width, 0.0};
        arm.side = perp(arm.out);
        arm.angle = std::atan2(arm.out.y(), arm.out.x());
        arms.push_back(arm);
      }
    }
    if (arms.empty()) continue;
    std::sort(arms.begin(), arms.end(), [](const Arm& a, const Arm& c) { return a.angle < c.angle; });
    // The polygon: hull of the road ends and the corners where neighbouring kerbs meet.
    std::vector<Vec2> points;
    for (const Arm& a : arms) {
      points.push_back(a.end + a.half * a.side);
      points.push_back(a.end - a.half * a.side);
    }
    for (size_t i = 0; i < arms.size() && arms.size() > 1; ++i) {
      const Arm& a = arms[i];
      const Arm& c = arms[(i + 1) % arms.size()];
      // Kerb lines p + t * a.out and q + u * c.out: solve p + t a.out = q + u c.out.
      const Vec2 p = a.end + a.half * a.side, q = c.end - c.half * c.side;
      Eigen::Matrix2d m;
      m.col(0) = a.out;
      m.col(1) = -c.out;
      if (std::abs(m.determinant()) < 1e-6) continue;
      const Vec2 tu = m.inverse() * (q - p);
      const Vec2 corner = p + tu.x() * a.out;
      // Behind both road ends and near the node (nearly collinear kerbs of a through street
      // meet far away or on the kerb itself).
      if (tu.x() <= 1e-9 && tu.y() <= 1e-9 && (corner - town.nodes[node].position).norm() < 2.0 * r)
        points.push_back(corner);
    }
    map.drivableAreas.push_back({int64_t(map.drivableAreas.size()) + 1, b.lift(convexHull(points))});

    // Connectors: from the lanes arriving on one arm to the lanes leaving on every other arm.
    for (const Arm& in : arms) {
      for (const Arm& out : arms) {
        if (in.street == out.street && in.atStart == out.atStart) continue;  // no U-turns
        // Arriving lanes: direction 1 (to->from) if the node is the street's start, else 0.
        const auto& arriving = b.streetLanes[in.street][in.atStart ? 1 : 0];
        const auto& leaving = b.streetLanes[out.street][out.atStart ? 0 : 1];
        // Lane i to lane i; where the counts differ, the extra lanes merge into (or split
        // from) the outermost lane of the narrower street, so no lane is a dead end.
        const size_t n = std::max(arriving.size(), leaving.size());
        for (size_t i = 0; i < n; ++i) {
          const LaneEnds& from = arriving[std::min(i, arriving.size() - 1)];
          const LaneEnds& to = leaving[std::min(i, leaving.size() - 1)];
          LaneSegment lane;
          lane.id = int64_t(map.laneSegments.size()) + 1;
          lane.isIntersection = true;
          lane.laneType = "VEHICLE";
          lane.leftLaneBoundary = b.lift(connectorCurve(from.leftEnd, from.endDir, to.leftStart, to.startDir));
          lane.rightLaneBoundary = b.lift(connectorCurve(from.rightEnd, from.endDir, to.rightStart, to.startDir));
          lane.leftLaneMarkType = "NONE";
          lane.rightLaneMarkType = "NONE";
          lane.predecessors.push_back(map.laneSegments[from.lane].id);
          lane.successors.push_back(map.laneSegments[to.lane].id);
          map.laneSegments[from.lane].successors.push_back(lane.id);
          map.laneSegments[to.lane].predecessors.push_back(lane.id);
          map.laneSegments.push_back(std::move(lane));
        }
      }
    }
    // Pedestrian crossings across every arm of a real junction, just inside it.
    if (arms.size() >= 3) {
      for (const Arm& a : arms) {
        const Vec2 near = a.end - 1.0 * a.out, far = a.end - 4.0 * a.out;
        PedestrianCrossing c;
        c.id = int64_t(map.pedestrianCrossings.size()) + 1;
        c.edge1 = b.lift(std::vector<Vec2>{near - a.half * a.side, near + a.half * a.side});
        c.edge2 = b.lift(std::vector<Vec2>{far - a.half * a.side, far + a.half * a.side});
        map.pedestrianCrossings.push_back(std::move(c));
      }
    }
  }
}

// The ground-height raster: the terrain within groundRadius of the drivable area, NaN elsewhere.
void buildGroundHeight(const TownOptions& o, TownMap& town) {
  const DrivableRaster raster = DrivableRaster::build(
      town.vectorMap, {.resolution = o.groundResolution, .margin = o.groundRadius + 2.0 * o.groundResolution},
      "procedural town");
  const GridGeometry& g = raster.geometry();
  // Dilate the drivable cells by a disc of radius groundRadius (cell centre distances).
  std::vector<uint8_t> near(g.cellCount(), 0);
  const double radiusCells = o.groundRadius / g.resolution;
  const int reach = int(std::floor(radiusCells));
  for (int row = 0; row < g.rows; ++row) {
    for (const DrivableRaster::Run& run : raster.runs(row)) {
      for (int dy = -reach; dy <= reach; ++dy) {
        const int rr = row + dy;
        if (rr < 0 || rr >= g.rows) continue;
        const int dx = int(std::floor(std::sqrt(radiusCells * radiusCells - double(dy * dy))));
        const int begin = std::max(0, run.begin - dx), end = std::min(g.cols, run.end + dx);
        std::fill(near.begin() + ptrdiff_t(g.index(begin, rr)), near.begin() + ptrdiff_t(g.index(0, rr)) + end, 1);
      }
    }
  }
  NpyArray& a = town.groundHeight;
  a.dtype = NpyDtype::Float16;
  a.shape = {size_t(g.rows), size_t(g.cols)};
  a.values.assign(g.cellCount(), std::numeric_limits<float>::quiet_NaN());
  for (int row = 0; row < g.rows; ++row) {
    for (int col = 0; col < g.cols; ++col) {
      const size_t i = g.index(col, row);
      if (near[i]) a.values[i] = halfToFloat(floatToHalf(float(town.terrain.height(g.cellCentre(col, row)))));
    }
  }
  // Pixel (col, row) covers city [origin + col * res, ...): image = (p - origin) / res.
  town.imgSim2City.R = Eigen::Matrix2d::Identity();
  town.imgSim2City.s = 1.0 / g.resolution;
  town.imgSim2City.t = -g.origin;
}

}  // namespace

TownMap generateTown(const TownOptions& o, uint64_t seed) {
  check(o.gridCols >= 2 && o.gridRows >= 2 && o.gridCols <= 50 && o.gridRows <= 50, "grid must be 2..50 junctions a side");
  check(o.blockSize >= 60.0 && o.blockSize <= 2000.0, "blockSize must be 60..2000 m");
  check(o.jitter >= 0.0 && o.jitter <= 0.15 * o.blockSize, "jitter must be 0..0.15 blockSize");
  check(o.removedEdgeFraction >= 0.0 && o.removedEdgeFraction <= 1.0, "removedEdgeFraction must be 0..1");
  check(o.curvedEdgeFraction >= 0.0 && o.curvedEdgeFraction <= 1.0, "curvedEdgeFraction must be 0..1");
  check(o.minRoadWidth >= 3.0 && o.maxRoadWidth >= o.minRoadWidth && o.maxRoadWidth <= 0.2 * o.blockSize,
        "road widths must be 3 m .. 0.2 blockSize, min <= max");
  check(o.corridors >= 0 && o.corridors <= 2, "corridors must be 0..2");
  check(o.corridorLength >= 100.0, "corridorLength must be >= 100 m");
  check(o.hillGrade >= 0.0 && o.hillGrade <= 0.3, "hillGrade must be 0..0.3");
  check(o.threeLaneWidth >= o.twoLaneWidth, "threeLaneWidth must be >= twoLaneWidth");
  check(o.junctionMargin >= 0.0 && o.junctionMargin <= 50.0, "junctionMargin must be 0..50 m");
  check(o.groundResolution > 0.0 && o.groundRadius >= 0.0, "ground raster resolution and radius must be positive");

  TownMap town;
  town.seed = seed;
  std::mt19937_64 rng(seed);
  buildNetwork(o, rng, town);
  Vec2 lo = town.nodes.front().position, hi = lo;
  for (const TownNode& n : town.nodes) lo = lo.cwiseMin(n.position), hi = hi.cwiseMax(n.position);
  town.terrain = HeightField::random(lo, hi, o.hillGrade, rng);
  Builder b{o, town, {}, {}, {}, {}};
  buildStreets(b);
  buildJunctions(b);
  buildGroundHeight(o, town);
  return town;
}

}  // namespace hdprior
