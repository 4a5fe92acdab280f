#pragma once
#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/graph/pose_graph.h"

namespace hdprior {

// The odometry drift model of the pose graph's between-factors, for any odometry source (the built-in
// lidar odometry, or a trajectory read from a file with or without covariances): variances added,
// per axis, to the relative pose's own covariance. Residual order [rotation (rad^2), translation (m^2)].
//   rotation:    (odometryRotationSigmaDegPerM * d)^2     (in rad^2)
//   translation: (odometryTranslationSigmaPerM * d)^2
// where d is the length of the relative translation (metres travelled between the two keyframes).
Eigen::Matrix<double, 6, 1> odometryDriftVariances(double distance, const PoseGraphOptions& options);

// The information of an odometry between-factor i_T_j = previousTThis: its covariance (body [v, w],
// zero when the source has none) reordered to [rotation, translation], plus the drift model. A
// covariance that is not positive on the diagonal or not finite gives a weak 1e-2 * identity.
Matrix6d odometryInformation(const Matrix6d& relativeCovariance, const SE3& previousTThis, const PoseGraphOptions& options);

// The drift model the graph starts from for an odometry source: the built-in odometry's per-metre
// sigmas, or for poses given in a file (`givenPoses`) graph.given_odometry_*_per_m in their place.
// An injected drift (odometry.drift) is not told to the model: the priors must show it.
PoseGraphOptions odometryDriftModel(const PoseGraphOptions& options, bool givenPoses);

}  // namespace hdprior
