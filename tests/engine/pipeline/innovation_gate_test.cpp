#include "engine/pipeline/innovation_gate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace hdprior {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A step's information over [rotation, translation] with these standard deviations per axis.
Matrix6d stepInformation(double rotationSigma, double translationSigma) {
  Eigen::Matrix<double, 6, 1> v;
  v << rotationSigma, rotationSigma, rotationSigma, translationSigma, translationSigma, translationSigma;
  return v.cwiseAbs2().cwiseInverse().asDiagonal();
}

SE3 forward(double metres) {
  SE3 T = SE3::Identity();
  T.translation().x() = metres;
  return T;
}

// A lateral prior (y observed only, vehicle heading +x) with this sigma.
Eigen::Matrix3d lateralInformation(double sigma) {
  return Eigen::Vector3d(0.0, 1.0 / (sigma * sigma), 0.0).asDiagonal();
}

TEST(InnovationGate, ChiSquareQuantilesAreTheTabulatedOnes) {
  EXPECT_NEAR(chiSquareQuantile(0.99, 1), 6.635, 1e-3);
  EXPECT_NEAR(chiSquareQuantile(0.99, 2), 9.210, 1e-3);
  EXPECT_NEAR(chiSquareQuantile(0.99, 3), 11.345, 1e-3);
  EXPECT_NEAR(chiSquareQuantile(0.95, 1), 3.841, 1e-3);
}

TEST(InnovationGate, AHeadingUncertaintyBecomesALateralOneAlongTheWay) {
  InnovationGate gate;
  gate.predict(Eigen::Vector3d::Zero(), forward(10.0), stepInformation(1.0 * kDeg, 0.01));
  // The start is fixed: after one step the covariance is the step's own.
  EXPECT_NEAR(gate.covariance()(0, 0), 1e-4, 1e-9);
  EXPECT_NEAR(gate.covariance()(2, 2), std::pow(1.0 * kDeg, 2), 1e-9);
  // The first step's yaw error turns the second: 10 m on, it is 10 m x 1 deg = 0.17 m across.
  gate.predict(Eigen::Vector3d(10.0, 0.0, 0.0), forward(10.0), stepInformation(1e-6, 0.01));
  EXPECT_NEAR(std::sqrt(gate.covariance()(1, 1)), std::hypot(0.01, 0.01, 10.0 * kDeg), 1e-3);
}

TEST(InnovationGate, AMatchFarAcrossTheRoadFromAGoodPredictionIsImprobable) {
  InnovationGate gate;
  gate.predict(Eigen::Vector3d::Zero(), forward(2.0), stepInformation(0.05 * kDeg, 0.05));
  const Eigen::Vector3d predicted(2.0, 0.0, 0.0);
  const InnovationGate::Test far = gate.test(predicted, Eigen::Vector3d(2.0, 2.0, 0.0), lateralInformation(0.3));
  EXPECT_EQ(far.dof, 1);
  EXPECT_GT(far.chi2, chiSquareQuantile(0.99, 1));
  const InnovationGate::Test near = gate.test(predicted, Eigen::Vector3d(2.0, 0.3, 0.0), lateralInformation(0.3));
  EXPECT_LT(near.chi2, chiSquareQuantile(0.99, 1));
  // What the prior does not observe (along, yaw) is not judged.
  const InnovationGate::Test along = gate.test(predicted, Eigen::Vector3d(7.0, 0.0, 0.5), lateralInformation(0.3));
  EXPECT_NEAR(along.chi2, 0.0, 1e-12);
}

TEST(InnovationGate, ADriftingPredictionAcceptsWhatAGoodOneRejects) {
  InnovationGate good, drifting;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector3d from(10.0 * i, 0.0, 0.0);
    good.predict(from, forward(10.0), stepInformation(0.01 * kDeg, 0.01));
    drifting.predict(from, forward(10.0), stepInformation(0.1 * kDeg, 0.07));  // 0.7 % and 1 deg / 100 m
  }
  const Eigen::Vector3d predicted(200.0, 0.0, 0.0), prior(200.0, 1.5, 0.0);
  EXPECT_GT(good.test(predicted, prior, lateralInformation(0.3)).chi2, chiSquareQuantile(0.99, 1));
  EXPECT_LT(drifting.test(predicted, prior, lateralInformation(0.3)).chi2, chiSquareQuantile(0.99, 1));
}

TEST(InnovationGate, APriorShrinksTheCovarianceInTheDirectionItObserves) {
  InnovationGate gate;
  gate.predict(Eigen::Vector3d::Zero(), forward(10.0), stepInformation(0.5 * kDeg, 0.2));
  const Eigen::Matrix3d before = gate.covariance();
  gate.update(lateralInformation(0.2));
  EXPECT_NEAR(gate.covariance()(0, 0), before(0, 0), 1e-12);  // along: unobserved, unchanged
  EXPECT_NEAR(gate.covariance()(1, 1), 1.0 / (1.0 / before(1, 1) + 25.0), 1e-9);
}

TEST(InnovationGate, TheGivenStartAcceptsOnlyMatchesWithinTheirOwnSigma) {
  const InnovationGate start;  // zero covariance: the first keyframe is the given start
  const Eigen::Vector3d predicted = Eigen::Vector3d::Zero();
  EXPECT_NEAR(start.test(predicted, Eigen::Vector3d(0.0, 0.6, 0.0), lateralInformation(0.3)).chi2, 4.0, 1e-9);
}

}  // namespace
}  // namespace hdprior
