#include "engine/sim/boundary_edit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/geom/smoothstep.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

// The ring starting at `first`.
Ring2 rotated(const Ring2& ring, size_t first) {
  Ring2 out(ring.begin() + ptrdiff_t(first), ring.end());
  out.insert(out.end(), ring.begin(), ring.begin() + ptrdiff_t(first));
  return out;
}

size_t sideSize(const Ring2& ring, RingSide side) { return (side.last + ring.size() - side.first) % ring.size() + 1; }

// Unit normal pointing into the polygon, of the edge a -> b.
Vec2 inward(const Vec2& a, const Vec2& b, double orientation) { return orientation * leftNormal(a, b); }

// The side replaced by `side`, followed by the rest of the ring; nullopt unless simple.
std::optional<Ring2> withSide(const Ring2& rot, size_t m, const Ring2& side) {
  Ring2 out = side;
  out.insert(out.end(), rot.begin() + ptrdiff_t(m), rot.end());
  if (!isSimpleRing(out)) return std::nullopt;
  return out;
}

}  // namespace

double polylineLength2(const Ring2& line) {
  double s = 0.0;
  for (size_t i = 1; i < line.size(); ++i) s += (line[i] - line[i - 1]).norm();
  return s;
}

std::vector<RingSide> ringSides(const Ring2& ring, double cornerDegrees) {
  const size_t n = ring.size();
  std::vector<size_t> corners;
  const double threshold = cornerDegrees * std::numbers::pi / 180.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i] - ring[(i + n - 1) % n], b = ring[(i + 1) % n] - ring[i];
    if (a.norm() < 1e-9 || b.norm() < 1e-9) continue;
    const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (std::abs(turn) > threshold) corners.push_back(i);
  }
  if (corners.size() < 3) {
    corners.clear();
    const double perimeter = polylineLength2(ring) + (ring.back() - ring.front()).norm();
    double s = 0.0;
    for (size_t i = 0; i < n && corners.size() < 4; ++i) {
      if (s >= perimeter * double(corners.size()) / 4.0) corners.push_back(i);
      s += (ring[(i + 1) % n] - ring[i]).norm();
    }
  }
  std::vector<RingSide> sides;
  for (size_t k = 0; k < corners.size(); ++k) sides.push_back({corners[k], corners[(k + 1) % corners.size()]});
  return sides;
}

Ring2 sideVertices(const Ring2& ring, RingSide side) {
  Ring2 out;
  for (size_t k = 0, m = sideSize(ring, side); k < m; ++k) out.push_back(ring[(side.first + k) % ring.size()]);
  return out;
}

std::optional<BoundaryEdit> narrowSide(const Ring2& ring, RingSide side, double inset) {
  const size_t n = ring.size(), m = sideSize(ring, side);
  if (m < 2 || m >= n) return std::nullopt;
  const double orientation = signedArea(ring) > 0.0 ? 1.0 : -1.0;
  const Ring2 rot = rotated(ring, side.first);
  const Ring2 world(rot.begin(), rot.begin() + ptrdiff_t(m));
  Ring2 moved = world;
  for (size_t k = 1; k + 1 < m; ++k) {
    const Vec2 n1 = inward(world[k - 1], world[k], orientation), n2 = inward(world[k], world[k + 1], orientation);
    const Vec2 bisector = (n1 + n2).normalized();
    moved[k] += inset / std::max(0.5, bisector.dot(n1)) * bisector;
  }
  // The ends slide along the neighbouring edges until they are `inset` off the side's line.
  const auto slide = [&](const Vec2& end, const Vec2& neighbour, const Vec2& normal) -> std::optional<Vec2> {
    const Vec2 e = neighbour - end;
    const double c = e.normalized().dot(normal);
    if (c < 0.3 || inset / c > 0.8 * e.norm()) return std::nullopt;
    return end + inset / c * e.normalized();
  };
  const auto a = slide(world[0], rot[n - 1], inward(world[0], world[1], orientation));
  const auto b = slide(world[m - 1], rot[m % n], inward(world[m - 2], world[m - 1], orientation));
  if (!a || !b) return std::nullopt;
  moved.front() = *a;
  moved.back() = *b;
  auto edited = withSide(rot, m, moved);
  if (!edited || std::abs(signedArea(*edited)) >= std::abs(signedArea(ring))) return std::nullopt;
  return BoundaryEdit{*edited, moved, world};
}

std::optional<BoundaryEdit> moveKerbStretch(const Ring2& ring, RingSide side, double s0, double length, double offset,
                                            double taper) {
  const size_t n = ring.size(), m = sideSize(ring, side);
  if (m < 2 || m > n) return std::nullopt;
  const double orientation = signedArea(ring) > 0.0 ? 1.0 : -1.0;
  const Ring2 rot = rotated(ring, side.first);
  const Ring2 world(rot.begin(), rot.begin() + ptrdiff_t(m));
  std::vector<double> at(m, 0.0);  // arc length of each vertex
  for (size_t k = 1; k < m; ++k) at[k] = at[k - 1] + (world[k] - world[k - 1]).norm();
  const double s1 = s0 + length;
  if (s0 < 0.0 || s1 > at.back() + 1e-9 || length < 2.0 * taper) return std::nullopt;
  // Stations: every metre of the stretch and its own vertices.
  std::vector<double> stations;
  for (double s = s0; s < s1 - 0.5; s += 1.0) stations.push_back(s);
  stations.push_back(s1);
  for (size_t k = 0; k < m; ++k)
    if (at[k] > s0 + 1e-6 && at[k] < s1 - 1e-6) stations.push_back(at[k]);
  std::sort(stations.begin(), stations.end());
  // Outward normal at a station: its edge's, or the mean of both edges' at a vertex.
  const auto pointAt = [&](double s, Vec2& outward) {
    const size_t k = std::min(size_t(std::upper_bound(at.begin(), at.end(), s) - at.begin()), m - 1);
    const size_t i = k == 0 ? 0 : k - 1;  // edge i -> i + 1 holds s
    outward = -inward(world[i], world[i + 1], orientation);
    if (std::abs(s - at[i]) < 1e-9 && i > 0)
      outward = (outward - inward(world[i - 1], world[i], orientation)).normalized();
    const double f = (s - at[i]) / std::max(at[i + 1] - at[i], 1e-12);
    return Vec2(world[i] + f * (world[i + 1] - world[i]));
  };
  BoundaryEdit edit;
  Ring2 moved;
  for (size_t k = 0; k < m && at[k] < s0 - 1e-6; ++k) moved.push_back(world[k]);
  for (double s : stations) {
    Vec2 outward;
    const Vec2 p = pointAt(s, outward);
    const Vec2 q = p + offset * smoothstep(std::min(s - s0, s1 - s) / taper) * outward;
    edit.worldStretch.push_back(p);
    edit.stretch.push_back(q);
    moved.push_back(q);
  }
  for (size_t k = 0; k < m; ++k)
    if (at[k] > s1 + 1e-6) moved.push_back(world[k]);
  auto edited = withSide(rot, m, moved);
  if (!edited) return std::nullopt;
  edit.ring = std::move(*edited);
  return edit;
}

}  // namespace hdprior
