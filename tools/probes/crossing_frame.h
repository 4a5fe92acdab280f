#pragma once
// A pedestrian crossing as the probes read it: its centre, its axis (along edge1), the direction
// across it, and its half length and half width.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "engine/io/vector_map.h"

namespace hdprior {

struct CrossingFrame {
  Eigen::Vector2d centre, axis, across;
  double halfLength = 0, halfWidth = 0;
  bool contains(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = p - centre;
    return std::abs(d.dot(axis)) <= halfLength && std::abs(d.dot(across)) <= halfWidth;
  }
};

inline CrossingFrame frameOf(const PedestrianCrossing& c) {
  const Eigen::Vector2d a0 = c.edge1[0].head<2>(), a1 = c.edge1[1].head<2>();
  Eigen::Vector2d b0 = c.edge2[0].head<2>(), b1 = c.edge2[1].head<2>();
  if ((a1 - a0).dot(b1 - b0) < 0) std::swap(b0, b1);
  CrossingFrame f;
  f.centre = (a0 + a1 + b0 + b1) / 4;
  f.axis = ((a1 - a0) + (b1 - b0)).normalized();
  f.across = {-f.axis.y(), f.axis.x()};
  f.halfLength = 0.5 * ((a1 - a0).norm() + (b1 - b0).norm()) / 2;
  f.halfWidth = std::abs(((a0 + a1) / 2 - (b0 + b1) / 2).dot(f.across)) / 2;
  return f;
}

}  // namespace hdprior
