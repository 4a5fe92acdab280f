#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/io/vector_map.h"

namespace hdprior {

// A point on a polygon's boundary with its outward unit normal and its arc length from the first vertex.
struct BoundarySample {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();
  double arc = 0.0;
};

// Samples every `spacing` metres along each edge of a closed polygon (at least one per edge), its
// normals outwards whichever way the vertices turn.
std::vector<BoundarySample> sampleBoundary(const Polyline3& polygon, double spacing);

// The perimeter of a closed polygon on the plane.
double perimeter(const Polyline3& polygon);

// The part of a closed polygon's boundary from arc length a0 to a1 (metres, a0 < a1 <= perimeter), vertices included.
std::vector<Eigen::Vector2d> boundaryBetween(const Polyline3& polygon, double a0, double a1);

}  // namespace hdprior
