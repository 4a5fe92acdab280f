#include "engine/changes/boundary_samples.h"

#include <algorithm>
#include <cmath>

#include "engine/geom/polygon2d.h"

namespace hdprior {

namespace {

Eigen::Vector2d vertex(const Polyline3& polygon, size_t i) { return polygon[i % polygon.size()].head<2>(); }

}  // namespace

double perimeter(const Polyline3& polygon) {
  double length = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) length += (vertex(polygon, i + 1) - vertex(polygon, i)).norm();
  return length;
}

std::vector<BoundarySample> sampleBoundary(const Polyline3& polygon, double spacing) {
  std::vector<BoundarySample> samples;
  const double turn = signedArea(ringOf(polygon)) >= 0.0 ? 1.0 : -1.0;  // outwards is right of a CCW edge
  double arc = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d p = vertex(polygon, i), q = vertex(polygon, i + 1);
    const double length = (q - p).norm();
    if (length < 1e-9) continue;
    const Eigen::Vector2d d = (q - p) / length;
    const Eigen::Vector2d normal = turn * Eigen::Vector2d(d.y(), -d.x());
    const int n = std::max(1, int(std::round(length / spacing)));
    for (int k = 0; k < n; ++k) {
      const double s = (k + 0.5) * length / n;
      samples.push_back({p + s * d, normal, arc + s});
    }
    arc += length;
  }
  return samples;
}

std::vector<Eigen::Vector2d> boundaryBetween(const Polyline3& polygon, double a0, double a1) {
  std::vector<Eigen::Vector2d> line;
  double arc = 0.0;
  for (size_t i = 0; i < polygon.size() && arc < a1; ++i) {
    const Eigen::Vector2d p = vertex(polygon, i), q = vertex(polygon, i + 1);
    const double length = (q - p).norm();
    const double from = std::max(a0, arc), to = std::min(a1, arc + length);
    if (length > 1e-9 && to > from) {
      const Eigen::Vector2d start = p + (from - arc) / length * (q - p);
      if (line.empty() || (line.back() - start).norm() > 1e-9) line.push_back(start);
      line.push_back(p + (to - arc) / length * (q - p));
    }
    arc += length;
  }
  return line;
}

}  // namespace hdprior
