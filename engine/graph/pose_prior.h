#pragma once
#include <Eigen/Core>

#include "engine/geom/information.h"
#include "engine/geom/se3.h"
#include "engine/option_fields.h"

namespace hdprior {

class GroundHeight;
struct MatchResult;

// An HD-map pose prior on a keyframe (paper: T = (R(psi*) R(theta) R(phi), [x*, y*, z*])):
// yaw, x, y from scan-to-map matching, z from the ground-height map, roll and pitch from
// odometry; information over (yaw, x, y, z) only.
struct PosePrior {
  SE3 pose = SE3::Identity();
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();  // order: yaw, x, y, z; the map taken as exact
  // The map's own x, y error, isotropic, not in `information`: the pose graph carries it, correlated
  // along the route or independent per prior (PoseGraphOptions::mapErrorLength).
  double mapSigma = 0.0;
};

struct PosePriorOptions {
  double egoHeight = 0.32;      // the ego origin above the ground surface (Argoverse: about 0.32 m)
  double altitudeSigma = 0.10;  // metres: the ground-height raster's accuracy at a known (x, y)
  // Added to the match's variance along the vehicle's heading: junction matches, the only ones that
  // observe it, are metres off along the road while their Laplace sigma says centimetres.
  double alongTrackSigma = 1.0;  // metres; 0 adds nothing
  // A match goes into the graph only if its innovation against the prediction is below this quantile
  // of chi-square (engine/pipeline/innovation_gate.h); 0: every match that is not rejected goes in.
  double innovationGateProbability = 0.99;
  // This many consecutive gated priors that agree with one another (each passes the gate of a
  // challenger prediction started at the first of them, without the graph's) say the prediction is
  // what went wrong (an odometry failure its covariance did not show): they all go in and the gate
  // follows them. 0: never.
  int reanchorPriors = 3;
};
std::vector<OptionField> optionFields(PosePriorOptions& o);  // its configuration keys (ego_height is vehicle.ego_height)


// The prior's information over the planar pose (x, y, yaw), the order of a match's.
Eigen::Matrix3d planarInformation(const PosePrior& prior);

// The same with the map's error added back: what the prior alone says about the pose.
Eigen::Matrix3d marginalPlanarInformation(const PosePrior& prior);

// The prior with its map error in its information, as an error of its own, independent of the others'.
PosePrior withIndependentMapError(const PosePrior& prior);

// The altitude z* of the ego origin at (x, y): ground height (bilinear) plus egoHeight; NaN
// outside the raster's region of interest.
double priorAltitude(const GroundHeight& ground, double x, double y, double egoHeight);

// Builds the prior from a match (its estimate and information over x, y, yaw) and the
// odometry pose that supplies roll and pitch, and the place in the directions the match does not
// observe (where its information is zero). Without altitude (NaN) z gets no information.
PosePrior makePosePrior(const MatchResult& match, const SE3& odometryPose, const GroundHeight& ground,
                        const PosePriorOptions& options = {});

// The prior's residual at a pose, as its factor sees it: (yaw, x, y, z) differences (yaw wrapped),
// and chi2 = r^T Omega r, the squared Mahalanobis distance before the robust loss.
struct PriorResidual {
  Eigen::Vector4d error = Eigen::Vector4d::Zero();
  double chi2 = 0.0;
};
PriorResidual priorResidual(const PosePrior& prior, const SE3& pose);

}  // namespace hdprior
