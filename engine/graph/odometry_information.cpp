#include "engine/graph/odometry_information.h"

#include <cmath>
#include <numbers>

namespace hdprior {
namespace {

double square(double x) { return x * x; }
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

Eigen::Matrix<double, 6, 1> odometryDriftVariances(double distance, const PoseGraphOptions& o) {
  const double rotation = square(radians(o.odometryRotationSigmaDegPerM) * distance);
  const double translation = square(o.odometryTranslationSigmaPerM * distance);
  Eigen::Matrix<double, 6, 1> v;
  v << rotation, rotation, rotation, translation, translation, translation;
  return v;
}

Matrix6d odometryInformation(const Matrix6d& relativeCovariance, const SE3& previousTThis, const PoseGraphOptions& options) {
  const Matrix6d& own = relativeCovariance;
  // [v, w] -> [w, v]: the between-factor's residual is [rotation, translation].
  Matrix6d covariance;
  covariance << own.bottomRightCorner<3, 3>(), own.bottomLeftCorner<3, 3>(), own.topRightCorner<3, 3>(), own.topLeftCorner<3, 3>();
  covariance.diagonal() += odometryDriftVariances(previousTThis.translation().norm(), options);
  // A registration that found too little overlap reports no covariance: trust it weakly.
  if (!(covariance.diagonal().minCoeff() > 0.0) || !covariance.allFinite()) return Matrix6d::Identity() * 1e-2;
  return covariance.inverse();
}

PoseGraphOptions odometryDriftModel(const PoseGraphOptions& options, bool givenPoses) {
  PoseGraphOptions out = options;
  if (givenPoses) {
    out.odometryTranslationSigmaPerM = options.givenOdometryTranslationSigmaPerM;
    out.odometryRotationSigmaDegPerM = options.givenOdometryRotationSigmaDegPerM;
  }
  return out;
}

}  // namespace hdprior
