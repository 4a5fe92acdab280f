#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

enum class MatchStatus {
  Accepted,    // all three directions observed
  Degenerate,  // some direction (along a straight road) is unobservable; information kept in the others
  Rejected,    // poor fit, too few points, inconsistent with the prediction, or out of time
};

const char* toString(MatchStatus status);

// The outcome of matching road points to the drivable area. Poses and covariances are over
// the city-frame SE(2) pose (x, y, yaw) of the points' frame (ego / key frame).
struct MatchResult {
  Eigen::Vector3d initial = Eigen::Vector3d::Zero();
  Eigen::Vector3d estimate = Eigen::Vector3d::Zero();
  // Information kept for the prior (zero in unobservable directions) and its pseudo-inverse.
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  // The same information were the map exact: the map's own x, y error (mapSigma, isotropic) left out,
  // so that the pose graph can carry it as an error correlated along the route (pose_graph.h).
  Eigen::Matrix3d informationGivenMap = Eigen::Matrix3d::Zero();
  double mapSigma = 0.0;
  // Eigen-decomposition of the drivable boundary's constraint on the pose in scaled units
  // (x, y, yaw * yawLength), ascending: which directions the map's edges observe.
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();
  Eigen::Matrix3d eigenvectors = Eigen::Matrix3d::Identity();
  int observableDirections = 0;
  // How far the pose can move (along, lateral metres, yaw radians; +infinity: unbounded) before the
  // road points leave the drivable area (match_uncertainty.h); zero when not computed.
  Eigen::Vector3d evidenceHalfWidths = Eigen::Vector3d::Zero();
  // The Laplace (score curvature) sigmas before widening, in the estimate's frame (along, lateral metres,
  // yaw radians; +infinity where unobservable); zero when not computed.
  Eigen::Vector3d laplaceSigmas = Eigen::Vector3d::Zero();
  MatchStatus status = MatchStatus::Rejected;
  std::string reason;        // why it is degenerate or rejected
  double score = 0.0;        // NDT score at the estimate on the finest grid
  double scorePerPoint = 0.0;
  double inlierRatio = 0.0;  // share of points on the drivable area at the estimate
  double gateChi2 = 0.0;     // Mahalanobis distance^2 of estimate - initial under the prediction
  int iterations = 0;
  // The start, every iterate of the backend (the 2-D NDT's Newton steps of every level, coarse to
  // fine; PCL's start and result), then the curb refinement's result if it moved the pose.
  std::vector<Eigen::Vector3d> path;
  double timeMs = 0.0;
  size_t points = 0;             // road points matched
  size_t curbPoints = 0;         // curb points given to the curb refinement
  size_t staleRegionPoints = 0;  // road points left out in regions where the map disagrees
};

}  // namespace hdprior
