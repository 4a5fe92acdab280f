#include "engine/eval/match_calibration.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace hdprior {
namespace {

// Errors drawn from the Gaussian the information describes are judged honest: median NEES near
// chi2(1)'s median 0.455 and about 0.27 % beyond 3 sigma, in every direction.
TEST(MatchCalibration, AnHonestGaussianIsJudgedHonest) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  std::vector<MatchErrorSample> samples;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d truth(100.0 * n01(rng), 50.0 * n01(rng), 3.0 * n01(rng));
    // A covariance in the vehicle frame (along 0.5 m, lateral 0.1 m, yaw 0.3 deg, correlated), rotated to the city.
    Eigen::Matrix3d local;
    local << 0.25, 0.01, 0.0005, 0.01, 0.01, 0.0001, 0.0005, 0.0001, std::pow(0.3 * M_PI / 180.0, 2);
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    R.topLeftCorner<2, 2>() << std::cos(truth.z()), -std::sin(truth.z()), std::sin(truth.z()), std::cos(truth.z());
    const Eigen::Matrix3d covariance = R * local * R.transpose();
    const Eigen::Matrix3d L = covariance.llt().matrixL();
    const Eigen::Vector3d estimate = truth + L * Eigen::Vector3d(n01(rng), n01(rng), n01(rng));
    samples.push_back(matchErrorSample(truth, estimate, covariance.inverse()));
  }
  const MatchCalibration c = calibrateMatches(samples);
  EXPECT_EQ(c.matches, 20000u);
  for (const DirectionCalibration* d : {&c.along, &c.lateral, &c.yaw}) {
    EXPECT_EQ(d->observed, 20000u);
    EXPECT_NEAR(d->medianNees, 0.455, 0.03);
    EXPECT_LT(d->beyond3Sigma, 0.006);
  }
  EXPECT_NEAR(c.along.rms, 0.5, 0.02);
  EXPECT_NEAR(c.lateral.rms, 0.1, 0.004);
  EXPECT_NEAR(c.yaw.rms * 180.0 / M_PI, 0.3, 0.01);
}

// Sigmas ten times too small show up as NEES 100 times too large and most errors beyond 3 sigma.
TEST(MatchCalibration, OverconfidentSigmasAreCaught) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n01;
  std::vector<MatchErrorSample> samples;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d truth(0, 0, 0.3), e(0.5 * n01(rng), 0.5 * n01(rng), 0.01 * n01(rng));
    const Eigen::Vector3d claimed(0.05, 0.05, 0.001);
    samples.push_back(matchErrorSample(truth, truth + e, claimed.cwiseProduct(claimed).cwiseInverse().asDiagonal()));
  }
  const MatchCalibration c = calibrateMatches(samples);
  EXPECT_GT(c.lateral.medianNees, 30.0);
  EXPECT_GT(c.lateral.beyond3Sigma, 0.6);
  EXPECT_GT(c.yaw.beyond3Sigma, 0.6);
}

// A degenerate prior (no information along the heading) reports the along direction unobservable
// and keeps lateral and yaw; the directions follow the truth's heading, not the city axes.
TEST(MatchCalibration, UnobservableDirectionsAreLeftOut) {
  const double heading = 0.7;
  const Eigen::Vector3d truth(10, 20, heading);
  const Eigen::Vector2d along(std::cos(heading), std::sin(heading)), left(-std::sin(heading), std::cos(heading));
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  information.topLeftCorner<2, 2>() = left * left.transpose() / (0.2 * 0.2);
  information(2, 2) = 1.0 / std::pow(0.01, 2);
  Eigen::Vector3d estimate = truth;
  estimate.head<2>() += 3.0 * along + 0.1 * left;
  estimate.z() += 0.02;
  const MatchErrorSample s = matchErrorSample(truth, estimate, information);
  EXPECT_NEAR(s.error(0), 3.0, 1e-12);
  EXPECT_NEAR(s.error(1), 0.1, 1e-12);
  EXPECT_NEAR(s.error(2), 0.02, 1e-12);
  EXPECT_TRUE(std::isinf(s.sigma(0)));
  EXPECT_NEAR(s.sigma(1), 0.2, 1e-9);
  EXPECT_NEAR(s.sigma(2), 0.01, 1e-9);
  const std::vector<MatchErrorSample> one = {s};
  const MatchCalibration c = calibrateMatches(one);
  EXPECT_EQ(c.along.observed, 0u);
  EXPECT_EQ(c.lateral.observed, 1u);
  EXPECT_NEAR(c.lateral.medianNees, 0.25, 1e-9);
  EXPECT_NEAR(c.yaw.beyond3Sigma, 0.0, 0.0);
}

}  // namespace
}  // namespace hdprior
