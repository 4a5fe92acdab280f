#pragma once
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/io/vector_map.h"

namespace hdprior {

// Plane geometry of map outlines (city x, y). A ring is a polygon's vertices without the
// first one repeated at the end.
using Ring2 = std::vector<Eigen::Vector2d>;

Ring2 ringOf(const Polyline3& closedOrOpen);  // drops a repeated last vertex
double signedArea(const Ring2& ring);           // positive counter-clockwise
bool ringContains(const Ring2& ring, const Eigen::Vector2d& p);  // even-odd rule
// No two non-adjacent edges touch.
bool isSimpleRing(const Ring2& ring);
double segmentDistance(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                       const Eigen::Vector2d& b1);
// Nearest distance between two polylines (a single point is a polyline too); `closedB` adds
// b's closing edge. +infinity when either is empty.
double polylineDistance(std::span<const Eigen::Vector2d> a, std::span<const Eigen::Vector2d> b, bool closedB);
// A crossing's outline: edge1, then edge2 back (a quadrilateral, whichever way edge2 runs).
Ring2 crossingOutline(const PedestrianCrossing& crossing);
// A convex quadrilateral near a rectangle moved outwards by `margin` on each side.
Ring2 grownQuad(const Ring2& quad, double margin);
// Unit normal to the left of a -> b.
Eigen::Vector2d leftNormal(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
// How far p lies to the left of a polyline (negative: right), by the nearest of the segments p
// projects inside; nullopt where it projects inside none.
std::optional<double> leftOffset(std::span<const Eigen::Vector2d> line, const Eigen::Vector2d& p);

}  // namespace hdprior
