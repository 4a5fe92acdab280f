#pragma once
#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/graph/pose_graph.h"

namespace hdprior {

// The upper `probability` quantile of the chi-square distribution with 1-3 degrees of freedom.
double chiSquareQuantile(double probability, int dof);

// Gates each keyframe's prior against the prediction it was matched from. The planar covariance
// (x, y, yaw, city frame) of the graph's latest keyframe is carried forward like a filter's: grown by
// each odometry step's covariance, shrunk by each prior that goes in. A prior whose innovation (its
// pose minus the prediction, in the directions it observes) is improbable under the prediction's
// covariance plus its own is left out: a match 2 m off across a road whose odometry is good to 0.1 m
// has latched onto a flush verge or the wrong side of an island, whatever its own sigma says.
class InnovationGate {
 public:
  // The first keyframe is the run's given start (the graph holds it fixed): zero covariance.
  InnovationGate() = default;

  // The prediction of the next keyframe: `from` (planar) moved by the odometry step
  // previousTThis, whose information is over the between-factor's residual [rotation, translation].
  void predict(const Eigen::Vector3d& from, const SE3& previousTThis, const Matrix6d& stepInformation);

  // (innovation)^T S^-1 (innovation) in the prior's observed directions, and how many there are.
  struct Test {
    double chi2 = 0.0;
    int dof = 0;
  };
  Test test(const Eigen::Vector3d& predicted, const Eigen::Vector3d& prior, const Eigen::Matrix3d& priorInformation) const;

  // The prior went into the graph: the covariance shrinks by its information.
  void update(const Eigen::Matrix3d& priorInformation);

  const Eigen::Matrix3d& covariance() const { return covariance_; }

 private:
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
};

}  // namespace hdprior
