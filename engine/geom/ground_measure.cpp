#include "engine/geom/ground_measure.h"

#include <cmath>

namespace hdprior {

GroundMeasure measureGround(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double headingYaw) {
  GroundMeasure m;
  m.from = from;
  m.to = to;
  m.heading = headingYaw;
  const Eigen::Vector2d d = (to - from).head<2>();
  const double c = std::cos(headingYaw), s = std::sin(headingYaw);
  m.along = c * d.x() + s * d.y();
  m.lateral = -s * d.x() + c * d.y();
  m.distance = d.norm();
  m.rise = to.z() - from.z();
  return m;
}

}  // namespace hdprior
