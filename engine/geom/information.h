#pragma once
#include <Eigen/Core>

namespace hdprior {

// Gaussians in information form (possibly singular: zero information in unobservable directions).

// The projector onto the directions in which an information matrix is not zero: eigenvalues above
// 1e-9 of the largest, and above `floor`.
Eigen::Matrix3d observedProjector(const Eigen::Matrix3d& information, double floor = 0.0);

// The information of a Gaussian whose covariance gains sigma^2 along the direction a (Woodbury;
// exact for a singular information too, e.g. a degenerate match's).
Eigen::Matrix3d withVarianceAlong(const Eigen::Matrix3d& information, const Eigen::Vector3d& a, double sigma);

// The same with infinite variance along a: a marginalised out (the Schur complement), the other
// directions' marginals unchanged; a becomes unobservable.
Eigen::Matrix3d marginalizedAlong(const Eigen::Matrix3d& information, const Eigen::Vector3d& a);

}  // namespace hdprior
