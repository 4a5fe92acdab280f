#include "engine/pipeline/planar_kalman.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "../geom/forward_step.h"
#include "engine/geom/angles.h"
#include "engine/pipeline/drift_model_likelihood.h"
#include "engine/odom/keyframe.h"

namespace hdprior {
namespace {

// A step's information over [rotation, translation] with these standard deviations per axis.
Matrix6d stepInformation(double rotationSigma, double translationSigma) {
  Eigen::Matrix<double, 6, 1> v;
  v << rotationSigma, rotationSigma, rotationSigma, translationSigma, translationSigma, translationSigma;
  return v.cwiseAbs2().cwiseInverse().asDiagonal();
}

using test::forward;

// A lateral prior (y observed only, vehicle heading +x) with this sigma.
Eigen::Matrix3d lateralInformation(double sigma) { return Eigen::Vector3d(0.0, 1.0 / (sigma * sigma), 0.0).asDiagonal(); }

// The same as a pose prior at (x, y), heading +x: sigma given the map, and the map's own sigma.
PosePrior lateralPrior(double x, double y, double sigma, double mapSigma) {
  PosePrior p;
  p.pose.translation() = Eigen::Vector3d(x, y, 0.0);
  p.information(2, 2) = 1.0 / (sigma * sigma);  // order yaw, x, y, z
  p.mapSigma = mapSigma;
  return p;
}

TEST(PlanarKalman, ChiSquareQuantilesAreTheTabulatedOnes) {
  EXPECT_NEAR(chiSquareQuantile(0.99, 1), 6.635, 1e-3);
  EXPECT_NEAR(chiSquareQuantile(0.99, 2), 9.210, 1e-3);
  EXPECT_NEAR(chiSquareQuantile(0.99, 3), 11.345, 1e-3);
  EXPECT_NEAR(chiSquareQuantile(0.95, 1), 3.841, 1e-3);
}

TEST(PlanarKalman, AHeadingUncertaintyBecomesALateralOneAlongTheWay) {
  PlanarKalman filter;
  filter.predict(forward(10.0), stepInformation(1.0 * kDegree, 0.01));
  // The start is fixed: after one step the covariance is the step's own.
  EXPECT_NEAR(filter.covariance()(0, 0), 1e-4, 1e-9);
  EXPECT_NEAR(filter.covariance()(2, 2), std::pow(1.0 * kDegree, 2), 1e-9);
  // The first step's yaw error turns the second: 10 m on, it is 10 m x 1 deg = 0.17 m across.
  filter.predict(forward(10.0), stepInformation(1e-6, 0.01));
  EXPECT_NEAR(std::sqrt(filter.covariance()(1, 1)), std::hypot(0.01, 0.01, 10.0 * kDegree), 1e-3);
  EXPECT_TRUE(filter.mean().isApprox(Eigen::Vector3d(20.0, 0.0, 0.0)));
}

TEST(PlanarKalman, AMatchFarAcrossTheRoadFromAGoodPredictionIsImprobable) {
  PlanarKalman filter;
  filter.predict(forward(2.0), stepInformation(0.05 * kDegree, 0.05));
  const PlanarKalman::Innovation far = filter.innovation(Eigen::Vector3d(2.0, 2.0, 0.0), lateralInformation(0.3));
  EXPECT_EQ(far.dof, 1);
  EXPECT_GT(far.chi2, chiSquareQuantile(0.99, 1));
  const PlanarKalman::Innovation near = filter.innovation(Eigen::Vector3d(2.0, 0.3, 0.0), lateralInformation(0.3));
  EXPECT_LT(near.chi2, chiSquareQuantile(0.99, 1));
  // What the prior does not observe (along, yaw) is not judged.
  EXPECT_NEAR(filter.innovation(Eigen::Vector3d(7.0, 0.0, 0.5), lateralInformation(0.3)).chi2, 0.0, 1e-12);
}

TEST(PlanarKalman, ADriftingPredictionAcceptsWhatAGoodOneRejects) {
  PlanarKalman good, drifting;
  for (int i = 0; i < 20; ++i) {
    good.predict(forward(10.0), stepInformation(0.01 * kDegree, 0.01));
    drifting.predict(forward(10.0), stepInformation(0.1 * kDegree, 0.07));  // 0.7 % and 1 deg / 100 m
  }
  const Eigen::Vector3d prior(200.0, 1.5, 0.0);
  EXPECT_GT(good.innovation(prior, lateralInformation(0.3)).chi2, chiSquareQuantile(0.99, 1));
  EXPECT_LT(drifting.innovation(prior, lateralInformation(0.3)).chi2, chiSquareQuantile(0.99, 1));
}

TEST(PlanarKalman, APriorCorrectsAndShrinksOnlyWhatItObserves) {
  PlanarKalman filter;
  filter.predict(forward(10.0), stepInformation(0.5 * kDegree, 0.2));
  const Eigen::Matrix3d before = filter.covariance();
  filter.update(filter.innovation(Eigen::Vector3d(10.0, 0.4, 0.0), lateralInformation(0.2)));
  EXPECT_NEAR(filter.covariance()(0, 0), before(0, 0), 1e-12);  // along: unobserved, unchanged
  EXPECT_NEAR(filter.covariance()(1, 1), 1.0 / (1.0 / before(1, 1) + 25.0), 1e-9);
  const double gain = before(1, 1) / (before(1, 1) + 0.04);
  EXPECT_NEAR(filter.mean().y(), gain * 0.4, 1e-9);
  EXPECT_NEAR(filter.mean().x(), 10.0, 1e-12);
}

TEST(PlanarKalman, TheGivenStartAcceptsOnlyMatchesWithinTheirOwnSigma) {
  const PlanarKalman start;  // zero covariance: the first keyframe is the given start
  EXPECT_NEAR(start.innovation(Eigen::Vector3d(0.0, 0.6, 0.0), lateralInformation(0.3)).chi2, 4.0, 1e-9);
}

// Odometry that turns 0.02 deg too far every 2 m (1 deg over 100 m), priors that are right with
// 0.1 m noise: the likeliest model is one loose enough to let the priors pull the drift out; with an
// odometry that is right, one tighter than the configured, so that the priors' noise does not move it.
DriftModelLikelihood driftRun(double yawBiasPerStep, double marginNats = 0.0) {
  PoseGraphOptions configured;  // 1e-4 per metre
  configured.driftModelMarginNats = marginNats;
  DriftModelLikelihood likelihood(configured, Eigen::Vector3d::Zero());
  Keyframe kf;
  kf.previousTThis = forward(2.0, yawBiasPerStep);
  kf.relativeCovariance = Matrix6d::Identity() * 1e-8;
  Eigen::Vector3d truth = Eigen::Vector3d::Zero();
  const double noise[5] = {0.1, -0.05, 0.08, -0.12, 0.02};
  for (int k = 1; k <= 100; ++k) {
    likelihood.step(kf);
    truth.x() += 2.0;
    likelihood.observe(lateralPrior(truth.x(), noise[k % 5], 0.1, 0.0));
  }
  return likelihood;
}

PoseGraphOptions likeliestModel(double yawBiasPerStep) { return driftRun(yawBiasPerStep).likeliest(); }

TEST(DriftModelLikelihood, PicksAModelLooseEnoughForTheDriftThePriorsShow) {
  const PoseGraphOptions configured;
  const PoseGraphOptions drifting = likeliestModel(0.02 * kDegree), exact = likeliestModel(0.0);
  EXPECT_GE(drifting.odometryRotationSigmaDegPerM, 10.0 * configured.odometryRotationSigmaDegPerM);
  EXPECT_LT(exact.odometryRotationSigmaDegPerM, 0.1 * configured.odometryRotationSigmaDegPerM);
  EXPECT_EQ(drifting.odometryTranslationSigmaPerM / configured.odometryTranslationSigmaPerM,
            drifting.odometryRotationSigmaDegPerM / configured.odometryRotationSigmaDegPerM);
}

// A looser model is taken only if it beats the tightest one by more than the margin; a drift the
// priors show clearly still gets through a margin of 2 nats.
TEST(DriftModelLikelihood, AMarginKeepsTheTightestModelWhereALooserOneIsBarelyLikelier) {
  const PoseGraphOptions configured;
  const double kWeakBias = 0.002 * kDegree;
  const DriftModelLikelihood weak = driftRun(kWeakBias);
  const auto scored = weak.scored();
  const double tightest = scored[0].factor * configured.odometryRotationSigmaDegPerM;
  double gain = 0.0;
  for (const auto& c : scored) gain = std::max(gain, c.logLikelihood - scored[0].logLikelihood);
  ASSERT_GT(gain, 0.0);
  ASSERT_GT(weak.likeliest().odometryRotationSigmaDegPerM, tightest);
  EXPECT_EQ(driftRun(kWeakBias, gain * 1.01).likeliest().odometryRotationSigmaDegPerM, tightest);
  EXPECT_GT(driftRun(kWeakBias, gain * 0.99).likeliest().odometryRotationSigmaDegPerM, tightest);
  EXPECT_GE(driftRun(0.02 * kDegree, 2.0).likeliest().odometryRotationSigmaDegPerM, 10.0 * configured.odometryRotationSigmaDegPerM);
}

// After a re-anchor (the odometry was metres off somewhere) the model is never tighter than the
// configured one: a right odometry is what the priors after it cannot tell from one that slipped.
TEST(DriftModelLikelihood, AfterARestartTheModelIsNoTighterThanTheConfigured) {
  const PoseGraphOptions configured;
  DriftModelLikelihood exact = driftRun(0.0);
  ASSERT_LT(exact.likeliest().odometryRotationSigmaDegPerM, configured.odometryRotationSigmaDegPerM);
  exact.restartAt(lateralPrior(202.0, 0.0, 0.1, 0.0));
  EXPECT_EQ(exact.likeliest().odometryRotationSigmaDegPerM, configured.odometryRotationSigmaDegPerM);
  DriftModelLikelihood drifting = driftRun(0.02 * kDegree);
  const double before = drifting.likeliest().odometryRotationSigmaDegPerM;
  drifting.restartAt(lateralPrior(202.0, 0.0, 0.1, 0.0));
  EXPECT_EQ(drifting.likeliest().odometryRotationSigmaDegPerM, before);
}

// A re-anchor after a stretch without priors: the odometry drifted 1.3 m there, and the prior that
// re-anchors is the one that shows it. It counts for every candidate, so the model is no longer the
// configured one the few priors before the stretch could not tell from a loose one.
TEST(DriftModelLikelihood, ThePriorThatReanchorsIsEvidenceOfTheDrift) {
  const PoseGraphOptions configured;  // 1e-4 per metre
  DriftModelLikelihood likelihood(configured, Eigen::Vector3d::Zero());
  Keyframe kf;
  kf.previousTThis = forward(2.0, 0.02 * kDegree);
  kf.relativeCovariance = Matrix6d::Identity() * 1e-8;
  for (int k = 1; k <= 60; ++k) {
    likelihood.step(kf);
    if (k <= 10) likelihood.observe(lateralPrior(2.0 * k, 0.0, 0.1, 0.0));
  }
  likelihood.restartAt(lateralPrior(120.0, 0.0, 0.1, 0.0));
  EXPECT_GE(likelihood.likeliest().odometryRotationSigmaDegPerM, 10.0 * configured.odometryRotationSigmaDegPerM);
}

// scored() is what metrics.json shows: each candidate's log-likelihood, and one chosen, the one the
// final solve takes (the tightest within the margin of the likeliest).
TEST(DriftModelLikelihood, ScoredShowsEveryCandidateAndTheOneChosen) {
  for (double margin : {0.0, 1.0, 100.0}) {
    const DriftModelLikelihood run = driftRun(0.002 * kDegree, margin);
    const auto scored = run.scored();
    ASSERT_EQ(scored.size(), 42u);  // 21 drift factors, field or independent
    int chosen = 0;
    for (size_t i = 0; i < scored.size(); ++i) {
      if (!scored[i].chosen) continue;
      ++chosen;
      EXPECT_EQ(run.likeliest().odometryRotationSigmaDegPerM, PoseGraphOptions{}.odometryRotationSigmaDegPerM * scored[i].factor);
      EXPECT_EQ(run.likeliest().mapErrorLength, scored[i].mapErrorLength);
    }
    EXPECT_EQ(chosen, 1) << margin;
    if (margin == 100.0) EXPECT_EQ(run.likeliest().odometryRotationSigmaDegPerM, PoseGraphOptions{}.odometryRotationSigmaDegPerM * scored[0].factor);
  }
}

// An odometry sure of itself (0.15 deg / 100 m) along +x and lateral priors that all sit 0.25 m to the left: the map's own error,
// shared by every prior (sigma 0.05 given the map, map sigma 0.2).
template <typename Observe>
void priorsSharingOneMapError(Observe observe, const std::function<void()>& step) {
  const double noise[5] = {0.03, -0.05, 0.04, -0.02, 0.0};
  for (int k = 1; k <= 80; ++k) {
    step();
    observe(lateralPrior(2.0 * k, 0.25 + noise[k % 5], 0.05, 0.2));
  }
}

TEST(PlanarKalman, AMapErrorFieldTakesASharedOffsetForTheMapsNotThePoses) {
  PlanarKalman independent, field(Eigen::Vector3d::Zero(), 50.0);
  for (PlanarKalman* f : {&independent, &field}) {
    priorsSharingOneMapError([&](const PosePrior& p) { f->update(f->innovation(p)); },
                             [&] { f->predict(forward(2.0), stepInformation(0.003 * kDegree, 0.005)); });
  }
  // Taken as independent, eighty priors 0.25 m off pull the pose most of the way; as one field, the
  // offset is the map's, learnt where the start pins the pose, and the pose stays near the truth.
  EXPECT_GT(independent.mean().y(), 0.15);
  EXPECT_LT(std::abs(field.mean().y()), 0.06);
  EXPECT_NEAR(field.mapOffset().y(), 0.25, 0.06);
  EXPECT_NEAR(field.mean().x(), 160.0, 1e-3);
}

PoseGraphOptions likeliestUnderSharedMapError(double mapErrorLength) {
  PoseGraphOptions configured;
  configured.mapErrorLength = mapErrorLength;
  DriftModelLikelihood likelihood(configured, Eigen::Vector3d::Zero());
  Keyframe kf;
  kf.previousTThis = forward(2.0);
  kf.relativeCovariance = Matrix6d::Identity() * 1e-8;
  priorsSharingOneMapError([&](const PosePrior& p) { likelihood.observe(p); }, [&] { likelihood.step(kf); });
  return likelihood.likeliest();
}

TEST(DriftModelLikelihood, PriorsSharingOneMapErrorLookLikeDriftUnlessTheMapErrorIsAField) {
  const PoseGraphOptions configured;
  EXPECT_GT(likeliestUnderSharedMapError(0.0).odometryRotationSigmaDegPerM, configured.odometryRotationSigmaDegPerM);
  const PoseGraphOptions field = likeliestUnderSharedMapError(50.0);
  EXPECT_LE(field.odometryRotationSigmaDegPerM, configured.odometryRotationSigmaDegPerM);
  EXPECT_EQ(field.mapErrorLength, 50.0);  // the field, not independent errors, explains them
}

TEST(DriftModelLikelihood, MapErrorsThatChangeFromPriorToPriorAreTakenAsIndependent) {
  PoseGraphOptions configured;
  configured.mapErrorLength = 50.0;
  DriftModelLikelihood likelihood(configured, Eigen::Vector3d::Zero());
  EXPECT_EQ(likelihood.scored().size(), 42u);  // 21 drift factors, field or independent
  Keyframe kf;
  kf.previousTThis = forward(2.0);
  kf.relativeCovariance = Matrix6d::Identity() * 1e-8;
  for (int k = 1; k <= 80; ++k) {  // 0.2 m to one side, then the other: no field 50 m long does that
    likelihood.step(kf);
    likelihood.observe(lateralPrior(2.0 * k, k % 2 ? 0.2 : -0.2, 0.05, 0.2));
  }
  EXPECT_EQ(likelihood.likeliest().mapErrorLength, 0.0);
}

}  // namespace
}  // namespace hdprior
