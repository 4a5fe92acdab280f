#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../geom/forward_step.h"
#include "engine/geom/angles.h"
#include "engine/graph/odometry_information.h"

namespace hdprior {
namespace {

using test::forward;

}  // namespace

// The drift model: per-metre sigmas times the distance, squared, per axis, in [rotation, translation].
TEST(OdometryInformation, DriftModelGrowsWithTheDistance) {
  PoseGraphOptions o;
  o.odometryTranslationSigmaPerM = 0.005;
  o.odometryRotationSigmaDegPerM = 0.01;
  const auto v = odometryDriftVariances(2.0, o);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(v[i], std::pow(0.02 * kDegree, 2), 1e-18) << i;
    EXPECT_NEAR(v[3 + i], 0.01 * 0.01, 1e-15) << i;
  }
  EXPECT_TRUE(odometryDriftVariances(0.0, o).isZero());  // no step, no drift
}

TEST(OdometryInformation, ReordersTheCovarianceAndAddsTheModel) {
  Matrix6d vw = Matrix6d::Zero();  // body [v, w]
  vw.diagonal() << 1e-4, 2e-4, 3e-4, 1e-6, 2e-6, 3e-6;
  vw(0, 5) = vw(5, 0) = 1e-6;  // v_x with w_z
  PoseGraphOptions o;
  o.odometryTranslationSigmaPerM = 0.01;
  o.odometryRotationSigmaDegPerM = 0.0;
  const Matrix6d information = odometryInformation(vw, forward(2.0), o);
  const Matrix6d covariance = information.inverse();
  EXPECT_NEAR(covariance(0, 0), 1e-6, 1e-12);            // rotation first
  EXPECT_NEAR(covariance(2, 2), 3e-6, 1e-12);
  EXPECT_NEAR(covariance(3, 3), 1e-4 + 4e-4, 1e-12);     // translation, plus (0.01 * 2 m)^2
  EXPECT_NEAR(covariance(5, 5), 3e-4 + 4e-4, 1e-12);
  EXPECT_NEAR(covariance(2, 3), 1e-6, 1e-12);            // w_z with v_x
  // Without a covariance (an external trajectory), the drift model alone.
  PoseGraphOptions model;
  model.odometryTranslationSigmaPerM = 0.01;
  model.odometryRotationSigmaDegPerM = 0.005;
  const Matrix6d modelOnly = odometryInformation(Matrix6d::Zero(), forward(2.0), model);
  EXPECT_NEAR(modelOnly(4, 4), 1.0 / 4e-4, 1e-6);
  EXPECT_NEAR(modelOnly(0, 0), 1.0 / std::pow(0.01 * kDegree, 2), 1e-3);
  // Nothing at all (no covariance, no model, or not finite): weak.
  PoseGraphOptions noModel;
  noModel.odometryTranslationSigmaPerM = noModel.odometryRotationSigmaDegPerM = 0.0;
  EXPECT_TRUE(odometryInformation(Matrix6d::Zero(), forward(2.0), noModel).isApprox(Matrix6d::Identity() * 1e-2));
  Matrix6d bad = vw;
  bad(1, 1) = std::nan("");
  EXPECT_TRUE(odometryInformation(bad, forward(2.0), o).isApprox(Matrix6d::Identity() * 1e-2));
}

// The defaults describe the undrifted built-in odometry (docs/method.md, The pose graph: the drift model).
TEST(OdometryInformation, DefaultsAreASmallDriftModel) {
  const PoseGraphOptions o;
  EXPECT_GT(o.odometryTranslationSigmaPerM, 0.0);
  EXPECT_LE(o.odometryTranslationSigmaPerM, 1e-3);
  EXPECT_GT(o.odometryRotationSigmaDegPerM, 0.0);
  EXPECT_LE(o.odometryRotationSigmaDegPerM, 1e-3);
}

// A trajectory from a file is judged by its own drift model (graph.given_odometry_*), not by the
// built-in odometry's; an injected drift is not told to it (the priors must show it).
TEST(OdometryInformation, GivenPosesTakeTheirOwnDriftModel) {
  PoseGraphOptions o;
  o.givenOdometryTranslationSigmaPerM = 0.005;
  o.givenOdometryRotationSigmaDegPerM = 0.02;
  const PoseGraphOptions builtIn = odometryDriftModel(o, false);
  EXPECT_EQ(builtIn.odometryTranslationSigmaPerM, PoseGraphOptions{}.odometryTranslationSigmaPerM);
  const PoseGraphOptions given = odometryDriftModel(o, true);
  EXPECT_EQ(given.odometryTranslationSigmaPerM, 0.005);
  EXPECT_EQ(given.odometryRotationSigmaDegPerM, 0.02);
  // Without a covariance of its own, a file's relative pose is weighted by the model alone.
  const SE3 step = makeSE3(Eigen::Quaterniond::Identity(), Eigen::Vector3d(2, 0, 0));
  const Matrix6d information = odometryInformation(Matrix6d::Zero(), step, given);
  EXPECT_NEAR(1.0 / std::sqrt(information(3, 3)), 0.01, 1e-12);  // 0.005 per m over 2 m
  EXPECT_NEAR(1.0 / std::sqrt(information(0, 0)), 0.04 * std::numbers::pi / 180.0, 1e-12);
}

}  // namespace hdprior
