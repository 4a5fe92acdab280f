#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/geom/se3.h"
#include "engine/odom/odometry_drift.h"

namespace hdprior {

// A seeded random walk on each relative motion: a rotation about a random axis-vector and a
// translation, each component normal with standard deviation sigma * sqrt(step length), so the
// error grows with the square root of the distance, as white noise on the velocity would.
struct RandomWalk {
  double translationSigma = 0.0;  // metres per sqrt(metre), per axis
  double rotationSigmaDeg = 0.0;  // degrees per sqrt(metre), per axis
  uint64_t seed = 1;

  bool active() const { return translationSigma != 0.0 || rotationSigmaDeg != 0.0; }
};

// "SIGMA_M,SIGMA_DEG" (per sqrt(metre)), each in [0, 1]; throws Error(source, reason) otherwise.
RandomWalk parseRandomWalk(const std::string& text, const std::string& source);

// A trajectory degraded as another system's odometry would be: each consecutive relative motion
// through driftedStep (scale, yaw and pitch per metre; odometry_drift.h), then perturbed by the
// random walk, composed from poses[0], which is kept. The same inputs give the same poses.
std::vector<SE3> degradedPoses(const std::vector<SE3>& poses, const OdometryDrift& drift, const RandomWalk& walk);

}  // namespace hdprior
