#include "engine/geom/polygon2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

bool segmentsCross(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  const double d1 = cross(a1 - a0, b0 - a0), d2 = cross(a1 - a0, b1 - a0);
  const double d3 = cross(b1 - b0, a0 - b0), d4 = cross(b1 - b0, a1 - b0);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

}  // namespace

Ring2 ringOf(const Polyline3& line) {
  Ring2 ring;
  for (const Eigen::Vector3d& v : line) ring.push_back(v.head<2>());
  if (ring.size() > 1 && (ring.front() - ring.back()).norm() < 1e-9) ring.pop_back();
  return ring;
}

double signedArea(const Ring2& ring) {
  double a = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) a += cross(ring[i], ring[(i + 1) % ring.size()]);
  return 0.5 * a;
}

bool ringContains(const Ring2& ring, const Vec2& p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 &a = ring[i], &b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

bool isSimpleRing(const Ring2& ring) {
  const size_t n = ring.size();
  if (n < 3) return false;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segmentsCross(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
    }
  return true;
}

double segmentDistance(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  if (segmentsCross(a0, a1, b0, b1)) return 0.0;
  return std::min({pointSegmentDistance(a0, b0, b1), pointSegmentDistance(a1, b0, b1),
                   pointSegmentDistance(b0, a0, a1), pointSegmentDistance(b1, a0, a1)});
}

double polylineDistance(std::span<const Vec2> a, std::span<const Vec2> b, bool closedB) {
  double best = std::numeric_limits<double>::infinity();
  if (a.empty() || b.empty()) return best;
  const size_t na = std::max<size_t>(a.size() - 1, 1);
  const size_t nb = closedB && b.size() > 2 ? b.size() : std::max<size_t>(b.size() - 1, 1);
  for (size_t j = 0; j < nb; ++j) {
    const Vec2 &b0 = b[j], &b1 = b[std::min((j + 1) % b.size(), b.size() - 1)];
    const Vec2 bLo = b0.cwiseMin(b1), bHi = b0.cwiseMax(b1);
    for (size_t i = 0; i < na; ++i) {
      const Vec2 &a0 = a[i], &a1 = a[std::min(i + 1, a.size() - 1)];
      // The boxes' gap bounds the distance from below: most pairs end here.
      const Vec2 gap = (a0.cwiseMin(a1) - bHi).cwiseMax(bLo - a0.cwiseMax(a1)).cwiseMax(0.0);
      if (gap.squaredNorm() >= best * best) continue;
      best = std::min(best, segmentDistance(a0, a1, b0, b1));
    }
  }
  return best;
}

Vec2 leftNormal(const Vec2& a, const Vec2& b) {
  const Vec2 d = (b - a).normalized();
  return {-d.y(), d.x()};
}

Ring2 crossingOutline(const PedestrianCrossing& c) {
  Ring2 out;
  for (const Eigen::Vector3d& p : c.edge1) out.push_back(p.head<2>());
  const Ring2 second = ringOf(c.edge2);
  const bool sameWay = second.size() < 2 || out.size() < 2 || (out.back() - out.front()).dot(second.back() - second.front()) >= 0.0;
  if (sameWay) out.insert(out.end(), second.rbegin(), second.rend());
  else out.insert(out.end(), second.begin(), second.end());
  return out;
}

Ring2 grownQuad(const Ring2& quad, double margin) {
  Ring2 out;
  const size_t n = quad.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& p = quad[i];
    const Eigen::Vector2d a = (p - quad[(i + n - 1) % n]).normalized(), b = (p - quad[(i + 1) % n]).normalized();
    out.push_back(p + margin * (a + b));
  }
  return out;
}

std::optional<double> leftOffset(std::span<const Eigen::Vector2d> line, const Eigen::Vector2d& p) {
  std::optional<double> best;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector2d d = line[i + 1] - line[i];
    const double length2 = d.squaredNorm();
    if (length2 < 1e-12) continue;
    const double t = (p - line[i]).dot(d) / length2;
    if (t < 0.0 || t > 1.0) continue;
    const double offset = (d.x() * (p.y() - line[i].y()) - d.y() * (p.x() - line[i].x())) / std::sqrt(length2);
    if (!best || std::abs(offset) < std::abs(*best)) best = offset;
  }
  return best;
}

}  // namespace hdprior
