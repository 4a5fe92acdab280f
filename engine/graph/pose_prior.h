#pragma once
#include <Eigen/Core>

#include "engine/geom/se3.h"

namespace hdprior {

class GroundHeight;
struct MatchResult;

// An HD-map pose prior on a keyframe (paper: T = (R(psi*) R(theta) R(phi), [x*, y*, z*])):
// yaw, x, y from scan-to-map matching, z from the ground-height map, roll and pitch from
// odometry; information over (yaw, x, y, z) only.
struct PosePrior {
  SE3 pose = SE3::Identity();
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();  // order: yaw, x, y, z
};

struct PosePriorOptions {
  double egoHeight = 0.32;      // the ego origin above the ground surface (Argoverse: about 0.32 m)
  double altitudeSigma = 0.10;  // metres: the ground-height raster's accuracy at a known (x, y)
};

// The altitude z* of the ego origin at (x, y): ground height (bilinear) plus egoHeight; NaN
// outside the raster's region of interest.
double priorAltitude(const GroundHeight& ground, double x, double y, double egoHeight);

// Builds the prior from a match (its estimate and information over x, y, yaw) and the
// odometry pose that supplies roll and pitch. Without altitude (NaN) z gets no information.
PosePrior makePosePrior(const MatchResult& match, const SE3& odometryPose, const GroundHeight& ground,
                        const PosePriorOptions& options = {});

}  // namespace hdprior
