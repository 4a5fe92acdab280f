#pragma once
#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/graph/pose_graph.h"
#include "engine/graph/pose_prior.h"

namespace hdprior {

// The upper `probability` quantile of the chi-square distribution with 1-3 degrees of freedom.
double chiSquareQuantile(double probability, int dof);

// A pose covariance that forgets the mean (100 m, 90 deg): PlanarKalman::widen by it, and the next
// prior alone sets what it observes.
inline const Eigen::Matrix3d kForgottenPose = Eigen::Vector3d(1e4, 1e4, 2.4674011002723395).asDiagonal();  // (pi/2)^2

// A Kalman filter over the planar pose (x, y, yaw, city frame) of the latest keyframe: odometry steps
// move it and grow its covariance, HD-map priors (possibly singular information) correct it. The prior
// stage runs one to gate priors against the graph's prediction (InnovationGate: the mean is set to
// the graph's pose before each step) and one per candidate drift model to weigh the models by how
// well they predict the priors (DriftModelLikelihood).
//
// With a map error length (PoseGraphOptions::mapErrorLength) the state also carries the map's 2-D
// offset at the latest prior, a Gauss-Markov field along the route as in the graph: a prior then
// observes pose + offset with its information given the map, and priors that share one map error
// are not taken for independent evidence. Without it a prior's map error is its own, in the
// information the caller passes.
class PlanarKalman {
 public:
  // The start: the run's given first pose (the graph holds it fixed), zero covariance.
  explicit PlanarKalman(const Eigen::Vector3d& start = Eigen::Vector3d::Zero(), double mapErrorLength = 0.0);

  void setMean(const Eigen::Vector3d& mean) { state_.head<3>() = mean; }
  // The pose's covariance grown by `poseCovariance` (x, y, yaw): what the mean says is trusted less.
  void widen(const Eigen::Matrix3d& poseCovariance) { covariance_.topLeftCorner<3, 3>() += poseCovariance; }

  // The odometry step previousTThis, whose information is over the between-factor's residual
  // [rotation, translation].
  void predict(const SE3& previousTThis, const Matrix6d& stepInformation);

  // A prior's pose and information (zero in what it does not observe) against the prediction. With
  // a map error length and mapSigma > 0 the information is the prior's given the map, and the map's
  // offset (sigma mapSigma) is predicted from the last prior's.
  struct Innovation {
    int dof = 0;            // directions the prior observes
    double chi2 = 0.0;      // y^T S^-1 y
    double logDensity = 0;  // of y under N(0, S)
    Eigen::Matrix3d basis = Eigen::Matrix3d::Zero();  // its first dof columns span what the prior observes
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    double mapSigma = 0.0;  // > 0: the prior observes the map offset too
  };
  Innovation innovation(const Eigen::Vector3d& prior, const Eigen::Matrix3d& priorInformation, double mapSigma = 0.0) const;
  // The same for a pose prior as the graph takes it: with its map error as a shared field (a map
  // error length and a map sigma) or as its own.
  Innovation innovation(const PosePrior& prior) const;

  // The prior goes in: mean and covariance corrected.
  void update(const Innovation& innovation);

  Eigen::Vector3d mean() const { return state_.head<3>(); }
  Eigen::Matrix3d covariance() const { return covariance_.topLeftCorner<3, 3>(); }
  Eigen::Vector2d mapOffset() const { return state_.segment<2>(3); }

 private:
  using Vector5d = Eigen::Matrix<double, 5, 1>;
  using Matrix5d = Eigen::Matrix<double, 5, 5>;
  struct State {
    Vector5d mean;
    Matrix5d covariance;
  };
  // The state with the map offset carried on to a prior of map sigma `mapSigma` here.
  State atPrior(double mapSigma) const;

  Vector5d state_ = Vector5d::Zero();  // x, y, yaw, map offset x, y
  Matrix5d covariance_ = Matrix5d::Zero();
  double mapErrorLength_ = 0.0;
  bool hasMapOffset_ = false;
  double metresSinceOffset_ = 0.0;
};

}  // namespace hdprior
