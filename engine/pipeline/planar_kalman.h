#pragma once
#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/graph/pose_graph.h"

namespace hdprior {

// The upper `probability` quantile of the chi-square distribution with 1-3 degrees of freedom.
double chiSquareQuantile(double probability, int dof);

// A Kalman filter over the planar pose (x, y, yaw, city frame) of the latest keyframe: odometry steps
// move it and grow its covariance, HD-map priors (possibly singular information) correct it. The prior
// stage runs one to gate priors against the graph's prediction (InnovationGate mode: the mean is set
// to the graph's pose before each step) and one per candidate drift model to weigh the models by
// how well they predict the priors (DriftModelLikelihood).
class PlanarKalman {
 public:
  // The start: the run's given first pose (the graph holds it fixed), zero covariance.
  explicit PlanarKalman(const Eigen::Vector3d& start = Eigen::Vector3d::Zero()) : mean_(start) {}

  void setMean(const Eigen::Vector3d& mean) { mean_ = mean; }

  // The odometry step previousTThis, whose information is over the between-factor's residual
  // [rotation, translation].
  void predict(const SE3& previousTThis, const Matrix6d& stepInformation);

  // A prior's pose and information (zero in what it does not observe) against the prediction.
  struct Innovation {
    int dof = 0;            // directions the prior observes
    double chi2 = 0.0;      // y^T S^-1 y
    double logDensity = 0;  // of y under N(0, S)
    Eigen::Matrix3d basis = Eigen::Matrix3d::Zero();  // its first dof columns span what the prior observes
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  };
  Innovation innovation(const Eigen::Vector3d& prior, const Eigen::Matrix3d& priorInformation) const;

  // The prior goes in: mean and covariance corrected.
  void update(const Innovation& innovation);

  const Eigen::Vector3d& mean() const { return mean_; }
  const Eigen::Matrix3d& covariance() const { return covariance_; }

 private:
  Eigen::Vector3d mean_;
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
};

}  // namespace hdprior
