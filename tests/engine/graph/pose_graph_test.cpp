// Pose-graph factors and optimisation: analytic (automatic) Jacobians of the prior and
// between factors against central differences, yaw wrapping, the HD-map prior built from a
// match and the ground height (on the real log), and PGO recovering a known trajectory from
// noisy odometry plus priors, incrementally and in batch.
#include "engine/geom/angles.h"
#include "engine/graph/pose_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <ceres/ceres.h>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/graph/pose_factors.h"
#include "engine/graph/pose_prior.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/ground_height.h"
#include "engine/match/match_result.h"
#include "test_data.h"

namespace hdprior {
namespace {

SE3 poseOf(double x, double y, double z, double yaw, double pitch = 0.0, double roll = 0.0) {
  SE3 T = SE3::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

// Compares the Jacobians of an automatically differentiated cost with central differences.
void expectJacobiansMatch(ceres::CostFunction& autodiff, ceres::CostFunction& numeric,
                          const std::vector<double*>& parameters, double tolerance) {
  const int m = autodiff.num_residuals();
  std::vector<std::vector<double>> ja, jn;
  std::vector<double*> pa, pn;
  for (int size : autodiff.parameter_block_sizes()) {
    ja.emplace_back(size_t(m * size));
    jn.emplace_back(size_t(m * size));
  }
  for (size_t b = 0; b < ja.size(); ++b) {
    pa.push_back(ja[b].data());
    pn.push_back(jn[b].data());
  }
  std::vector<double> ra(static_cast<size_t>(m)), rn(static_cast<size_t>(m));
  ASSERT_TRUE(autodiff.Evaluate(parameters.data(), ra.data(), pa.data()));
  ASSERT_TRUE(numeric.Evaluate(parameters.data(), rn.data(), pn.data()));
  for (int k = 0; k < m; ++k) EXPECT_NEAR(ra[size_t(k)], rn[size_t(k)], 1e-12);
  double largest = 0;
  for (size_t b = 0; b < ja.size(); ++b) {
    for (size_t k = 0; k < ja[b].size(); ++k) {
      EXPECT_NEAR(ja[b][k], jn[b][k], tolerance) << "block " << b << " entry " << k;
      largest = std::max(largest, std::abs(ja[b][k]));
    }
  }
  EXPECT_GT(largest, 0.1);  // the Jacobians are not trivially zero
}

TEST(PoseFactors, PriorJacobiansMatchCentralDifferences) {
  const SE3 prior = poseOf(10, -4, 2, 0.7, 0.02, -0.01);
  Eigen::Matrix4d info;
  info << 400, 10, -5, 0, 10, 25, 3, 0, -5, 3, 30, 0, 0, 0, 0, 100;
  const PriorFactor f(prior, sqrtInformation<4>(info));
  ceres::AutoDiffCostFunction<PriorFactor, 4, 4, 3, 2> autodiff(new PriorFactor(f));
  ceres::NumericDiffCostFunction<PriorFactor, ceres::CENTRAL, 4, 4, 3, 2> numeric(new PriorFactor(f));
  Eigen::Quaterniond q(poseOf(0, 0, 0, 0.9, 0.05, 0.03).rotation());
  Eigen::Vector3d t(10.5, -3.7, 2.2);
  Eigen::Vector2d mapOffset(0.15, -0.1);
  expectJacobiansMatch(autodiff, numeric, {q.coeffs().data(), t.data(), mapOffset.data()}, 1e-6);
}

TEST(PoseFactors, BetweenJacobiansMatchCentralDifferences) {
  Eigen::Matrix<double, 6, 6> info = Eigen::Matrix<double, 6, 6>::Identity() * 100.0;
  info(0, 3) = info(3, 0) = 5.0;
  const BetweenFactor f(poseOf(2.0, 0.1, 0.0, 0.05), sqrtInformation<6>(info));
  ceres::AutoDiffCostFunction<BetweenFactor, 6, 4, 3, 4, 3> autodiff(new BetweenFactor(f));
  ceres::NumericDiffCostFunction<BetweenFactor, ceres::CENTRAL, 6, 4, 3, 4, 3> numeric(new BetweenFactor(f));
  Eigen::Quaterniond qi(poseOf(0, 0, 0, 0.3, 0.02).rotation()), qj(poseOf(0, 0, 0, 0.36, -0.01, 0.02).rotation());
  Eigen::Vector3d ti(1, 2, 3), tj(2.9, 2.8, 3.1);
  expectJacobiansMatch(autodiff, numeric, {qi.coeffs().data(), ti.data(), qj.coeffs().data(), tj.data()}, 1e-6);
}

TEST(PoseFactors, ResidualsVanishAtTheMeasurementAndYawWraps) {
  const SE3 a = poseOf(1, 2, 3, 0.4, 0.01), b = poseOf(3, 1, 3.2, 0.5, -0.02, 0.01);
  const BetweenFactor between(a.inverse() * b, Eigen::Matrix<double, 6, 6>::Identity());
  Eigen::Quaterniond qa(a.rotation()), qb(b.rotation());
  Eigen::Vector3d ta = a.translation(), tb = b.translation();
  double r6[6];
  between(qa.coeffs().data(), ta.data(), qb.coeffs().data(), tb.data(), r6);
  const Eigen::Map<Eigen::Matrix<double, 6, 1>> residual6(r6);
  EXPECT_LT(residual6.norm(), 1e-12);
  // b 0.1 m further along a's x axis than measured: the translation residual, in a's frame, alone sees it.
  Eigen::Vector3d tb2 = tb + a.rotation() * Eigen::Vector3d(0.1, 0, 0);
  between(qa.coeffs().data(), ta.data(), qb.coeffs().data(), tb2.data(), r6);
  EXPECT_LT(residual6.head<3>().norm(), 1e-12);
  EXPECT_TRUE(residual6.tail<3>().isApprox(Eigen::Vector3d(0.1, 0, 0), 1e-9)) << residual6.transpose();

  const PriorFactor prior(poseOf(0, 0, 0, 179 * kDegree), Eigen::Matrix4d::Identity());
  Eigen::Quaterniond q(poseOf(0, 0, 0, -179 * kDegree).rotation());
  Eigen::Vector3d t(0, 0, 0);
  double r4[4];
  const Eigen::Vector2d noMapError = Eigen::Vector2d::Zero();
  prior(q.coeffs().data(), t.data(), noMapError.data(), r4);
  EXPECT_NEAR(r4[0], 2 * kDegree, 1e-12);  // not -358 degrees
}

TEST(PosePrior, ResidualIsWhatItsFactorWhitensAndItsChi2) {
  PosePrior prior;
  prior.pose = poseOf(10, 20, 1, 179 * kDegree, 0.02, -0.01);
  prior.information = Eigen::Vector4d(100, 4, 9, 25).asDiagonal();
  const SE3 at = poseOf(10.5, 19.7, 1.2, -178 * kDegree, 0.03, 0.01);
  const PriorResidual r = priorResidual(prior, at);
  EXPECT_NEAR(r.error(0), 3 * kDegree, 1e-9);
  EXPECT_NEAR(r.error(1), 0.5, 1e-12);
  EXPECT_NEAR(r.error(2), -0.3, 1e-12);
  EXPECT_NEAR(r.error(3), 0.2, 1e-12);
  // The factor's whitened residual has the same squared norm.
  const PriorFactor factor(prior.pose, sqrtInformation<4>(prior.information));
  Eigen::Quaterniond q(at.rotation());
  Eigen::Vector3d t = at.translation();
  Eigen::Vector4d whitened;
  const Eigen::Vector2d noMapError = Eigen::Vector2d::Zero();
  factor(q.coeffs().data(), t.data(), noMapError.data(), whitened.data());
  EXPECT_NEAR(r.chi2, whitened.squaredNorm(), 1e-9);
  EXPECT_NEAR(r.chi2, 100 * std::pow(3 * kDegree, 2) + 4 * 0.25 + 9 * 0.09 + 25 * 0.04, 1e-9);
}

TEST(PosePrior, AltitudeFromTheRealGroundHeightMatchesTheGroundTruth) {
  const ArgoverseLog log(test::sharedLog());
  const GroundHeight ground = readGroundHeight(log.mapFiles().groundHeight, log.mapFiles().sim2);
  const SE3 truth = log.cityTEgo().at(log.sweepTimestamps()[0]);
  MatchResult match;
  match.estimate = planarPose(truth);
  match.information = match.informationGivenMap = Eigen::Vector3d(100, 200, 3000).asDiagonal();
  const SE3 odometry = truth * poseOf(0.5, -0.3, 0.4, 0.02);  // wrong by a little, incl. z
  const PosePrior prior = makePosePrior(match, odometry, ground, {.alongTrackSigma = 0.0});
  EXPECT_NEAR(prior.pose.translation().z(), truth.translation().z(), 0.10);  // ego 0.32 m above the raster
  EXPECT_NEAR(prior.pose.translation().x(), truth.translation().x(), 1e-9);
  EXPECT_NEAR(yawOf(prior.pose), yawOf(truth), 1e-9);
  // Roll and pitch are the odometry's.
  EXPECT_TRUE(levelRotation(prior.pose).isApprox(levelRotation(odometry), 1e-9));
  // Information reordered to (yaw, x, y, z).
  EXPECT_DOUBLE_EQ(prior.information(0, 0), 3000);
  EXPECT_DOUBLE_EQ(prior.information(1, 1), 100);
  EXPECT_DOUBLE_EQ(prior.information(2, 2), 200);
  EXPECT_DOUBLE_EQ(prior.information(3, 3), 100);  // 0.1 m altitude sigma
  EXPECT_TRUE(std::isnan(priorAltitude(ground, 0.0, 0.0, 0.32)));  // far outside the map
}

TEST(PosePrior, TheAlongTrackSigmaWidensOnlyTheDirectionOfTheHeading) {
  const double yaw = 0.6;
  const Eigen::Vector3d along(std::cos(yaw), std::sin(yaw), 0.0);
  Eigen::Matrix3d covariance;  // a full, correlated match covariance over (x, y, yaw)
  covariance << 0.004, 0.001, 0.0002, 0.001, 0.003, -0.0001, 0.0002, -0.0001, 0.00005;
  const Eigen::Matrix3d widened = withVarianceAlong(covariance.inverse(), along, 1.5).inverse();
  EXPECT_TRUE(widened.isApprox(covariance + 2.25 * along * along.transpose(), 1e-9));
  // A corridor match (nothing observed along the road) stays as it is, singular and all.
  const Eigen::Vector3d across(-along.y(), along.x(), 0.0);
  const Eigen::Matrix3d corridor = 400.0 * across * across.transpose() + Eigen::Vector3d(0, 0, 3000).asDiagonal().toDenseMatrix();
  EXPECT_TRUE(withVarianceAlong(corridor, along, 1.5).isApprox(corridor, 1e-12));
  // In the prior (yaw, x, y, z order): the lateral and yaw information are kept where the match
  // information is diagonal in the vehicle's axes; along the heading it drops to 1 / (sigma^2 + 1 / 100).
  MatchResult match;
  match.estimate = Eigen::Vector3d(0, 0, yaw);
  match.information = 100.0 * along * along.transpose() + 400.0 * across * across.transpose();
  match.information(2, 2) = 3000.0;
  match.informationGivenMap = match.information;
  const GroundHeight none;
  const PosePrior prior = makePosePrior(match, poseOf(0, 0, 0, yaw), none, {.alongTrackSigma = 1.5});
  const Eigen::Vector3d alongYawXY(0, along.x(), along.y()), acrossYawXY(0, across.x(), across.y());
  const Eigen::Matrix3d I = prior.information.topLeftCorner<3, 3>();
  EXPECT_NEAR(alongYawXY.dot(I * alongYawXY), 1.0 / (2.25 + 0.01), 1e-9);
  EXPECT_NEAR(acrossYawXY.dot(I * acrossYawXY), 400.0, 1e-9);
  EXPECT_NEAR(I(0, 0), 3000.0, 1e-9);
}

TEST(PosePrior, TheAlongTrackSigmaFollowsTheHeadingWhereTheMatchLeavesYawFree) {
  // A match that observes one combination, the lateral place 1.2 m ahead (y + 1.2 yaw), 2.4 m off:
  // its prior's yaw is a point of that constraint far from the heading (0 here), and the along-track
  // sigma must not widen the lateral place it observes.
  const Eigen::Vector3d n = Eigen::Vector3d(0.0, 1.0, 1.2).normalized();
  MatchResult match;
  match.estimate = Eigen::Vector3d(0.0, 2.4, 0.0);
  match.information = match.informationGivenMap = 40.0 * n * n.transpose();
  const GroundHeight none;
  const PosePrior prior = makePosePrior(match, poseOf(0, 0, 0, 0), none, {.alongTrackSigma = 1.0});
  EXPECT_GT(std::abs(yawOf(prior.pose)), 0.5);
  EXPECT_TRUE(planarInformation(prior).isApprox(match.information, 1e-12));
}

TEST(PosePrior, ADegenerateMatchTakesItsAlongTrackPlaceAndAltitudeFromTheOdometry) {
  const ArgoverseLog log(test::sharedLog());
  const GroundHeight ground = readGroundHeight(log.mapFiles().groundHeight, log.mapFiles().sim2);
  const SE3 truth = log.cityTEgo().at(log.sweepTimestamps()[0]);
  const Eigen::Vector3d t = planarPose(truth);
  const Eigen::Vector2d along(std::cos(t.z()), std::sin(t.z())), across(-along.y(), along.x());
  MatchResult match;  // a corridor: lateral and yaw observed, 3 m wrong along the road, 0.2 m across
  match.estimate = t + Eigen::Vector3d(3.0 * along.x() + 0.2 * across.x(), 3.0 * along.y() + 0.2 * across.y(), 0.01);
  match.information.setZero();
  match.information.topLeftCorner<2, 2>() = 400.0 * across * across.transpose();
  match.information(2, 2) = 3000.0;
  match.informationGivenMap = match.information;
  const PosePrior prior = makePosePrior(match, truth, ground);
  const Eigen::Vector2d expected = t.head<2>() + 0.2 * across;
  EXPECT_NEAR((prior.pose.translation().head<2>() - expected).norm(), 0.0, 1e-9);
  EXPECT_NEAR(yawOf(prior.pose), t.z() + 0.01, 1e-9);
  EXPECT_NEAR(prior.pose.translation().z(), priorAltitude(ground, expected.x(), expected.y(), 0.32), 1e-9);
  // The road climbs here, so the estimate's own place would have put the altitude elsewhere.
  const Eigen::Vector3d e = match.estimate;
  EXPECT_GT(std::abs(priorAltitude(ground, e.x(), e.y(), 0.32) - prior.pose.translation().z()), 0.05);
}

// A winding, hilly ground-truth trajectory of keyframes 2 m apart.
std::vector<SE3> truthTrajectory(int n) {
  std::vector<SE3> poses;
  double x = 0, y = 0, yaw = 0;
  for (int k = 0; k < n; ++k) {
    poses.push_back(poseOf(x, y, 0.02 * x + std::sin(0.05 * k), yaw, 0.02, 0.005 * std::sin(0.3 * k)));
    yaw += 0.04 * std::sin(0.1 * k);
    x += 2.0 * std::cos(yaw);
    y += 2.0 * std::sin(yaw);
  }
  return poses;
}

double rmse(const std::vector<SE3>& a, const std::vector<SE3>& b) {
  double sum = 0;
  for (size_t k = 0; k < a.size(); ++k) sum += (a[k].translation() - b[k].translation()).squaredNorm();
  return std::sqrt(sum / double(a.size()));
}

struct Scenario {
  std::vector<SE3> truth, odometryPoses, relative;
  std::vector<PosePrior> priors;  // one per 4th keyframe
};

Scenario makeScenario(int n) {
  Scenario s;
  s.truth = truthTrajectory(n);
  std::mt19937 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  s.odometryPoses.push_back(s.truth[0]);
  for (int k = 1; k < n; ++k) {
    const SE3 exact = s.truth[size_t(k) - 1].inverse() * s.truth[size_t(k)];
    // Odometry: a yaw bias plus noise, 2 % scale noise.
    const SE3 noisy = exact * poseOf(0.04 * unit(rng), 0.02 * unit(rng), 0.01 * unit(rng), 0.004 + 0.002 * unit(rng),
                                     0.001 * unit(rng), 0.001 * unit(rng));
    s.relative.push_back(noisy);
    s.odometryPoses.push_back(s.odometryPoses.back() * noisy);
  }
  for (int k = 0; k < n; k += 4) {
    PosePrior p;
    const SE3& t = s.truth[size_t(k)];
    p.pose = t * poseOf(0.1 * unit(rng), 0.1 * unit(rng), 0.05 * unit(rng), 0.3 * kDegree * unit(rng));
    p.pose.linear() = Eigen::AngleAxisd(yawOf(p.pose), Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                      levelRotation(s.odometryPoses[size_t(k)]);
    p.information = Eigen::Vector4d(1.0 / std::pow(0.3 * kDegree, 2), 100, 100, 400).asDiagonal();
    s.priors.push_back(p);
  }
  return s;
}

Matrix6d odometryInformation() {
  Matrix6d info = Matrix6d::Zero();
  info.diagonal() << 1 / std::pow(0.003, 2), 1 / std::pow(0.003, 2), 1 / std::pow(0.003, 2), 1 / std::pow(0.04, 2),
      1 / std::pow(0.03, 2), 1 / std::pow(0.02, 2);
  return info;
}

TEST(PoseGraph, RecoversAKnownTrajectoryFromNoisyOdometryAndPriors) {
  const int n = 60;
  const Scenario s = makeScenario(n);
  PoseGraph graph;
  for (int k = 0; k < n; ++k) graph.addKeyframe(int64_t(k) * 1'000'000'000, s.odometryPoses[size_t(k)]);
  for (int k = 1; k < n; ++k) graph.addOdometry(size_t(k) - 1, size_t(k), s.relative[size_t(k) - 1], odometryInformation());
  for (size_t p = 0; p < s.priors.size(); ++p) graph.addPrior(p * 4, s.priors[p]);
  const double before = rmse(s.odometryPoses, s.truth);
  const SolveSummary summary = graph.solve();
  const double after = rmse(graph.poses(), s.truth);
  std::printf("ATE RMSE odometry %.3f m -> with priors %.3f m (%d iterations)\n", before, after, summary.iterations);
  EXPECT_GT(before, 1.0);
  EXPECT_LT(after, 0.15);
  EXPECT_LT(after * 3.0, before);
  EXPECT_LT(summary.finalCost, summary.initialCost);
}

TEST(PoseGraph, IncrementalSolvesEndWhereTheBatchSolveDoes) {
  const int n = 40;
  const Scenario s = makeScenario(n);
  PoseGraph incremental, batch;
  for (int k = 0; k < n; ++k) {
    for (PoseGraph* g : {&incremental, &batch}) {
      g->addKeyframe(int64_t(k) * 1'000'000'000, k == 0 ? s.odometryPoses[0]
                                                          : g->pose(size_t(k) - 1) * s.relative[size_t(k) - 1]);
      if (k > 0) g->addOdometry(size_t(k) - 1, size_t(k), s.relative[size_t(k) - 1], odometryInformation());
      if (k % 4 == 0) g->addPrior(size_t(k), s.priors[size_t(k / 4)]);
    }
    incremental.solve();  // warm-started from the previous solution
  }
  incremental.solve();
  batch.solve();
  for (int k = 0; k < n; ++k) {
    EXPECT_LT((incremental.pose(size_t(k)).translation() - batch.pose(size_t(k)).translation()).norm(), 1e-3) << k;
  }
  EXPECT_LT(rmse(incremental.poses(), s.truth), 0.15);
}

TEST(PoseGraph, CorrectsEverySweepByInterpolatingTheKeyframeCorrections) {
  PoseGraph graph;
  graph.addKeyframe(0, poseOf(0, 0, 0, 0));
  graph.addKeyframe(10, poseOf(10, 0, 0, 0));
  graph.addKeyframe(20, poseOf(20, 0, 0, 0));
  PosePrior b, c;
  b.pose = poseOf(10, 2, 0, 0);
  c.pose = poseOf(20, 3, 0, 0);
  b.information = c.information = Eigen::Vector4d(1e6, 1e6, 1e6, 1e6).asDiagonal();
  graph.addPrior(1, b);
  graph.addPrior(2, c);
  graph.addOdometry(0, 1, poseOf(10, 0, 0, 0), Matrix6d::Identity() * 1e-6);
  graph.addOdometry(1, 2, poseOf(10, 0, 0, 0), Matrix6d::Identity() * 1e-6);
  graph.solve();
  const PoseTrajectory sweeps({-5, 0, 5, 10, 15, 20, 25},
                              {poseOf(-5, 0, 0, 0), poseOf(0, 0, 0, 0), poseOf(5, 0, 0, 0), poseOf(10, 0, 0, 0),
                               poseOf(15, 0, 0, 0), poseOf(20, 0, 0, 0), poseOf(25, 0, 0, 0)});
  const PoseTrajectory corrected = graph.correct(sweeps);
  EXPECT_NEAR(corrected.poses()[0].translation().y(), 0.0, 1e-3);  // before the first: its correction
  EXPECT_NEAR(corrected.poses()[1].translation().y(), 0.0, 1e-3);
  EXPECT_NEAR(corrected.poses()[2].translation().y(), 1.0, 1e-3);  // halfway
  EXPECT_NEAR(corrected.poses()[3].translation().y(), 2.0, 1e-3);
  EXPECT_NEAR(corrected.poses()[4].translation().y(), 2.5, 1e-3);
  EXPECT_NEAR(corrected.poses()[5].translation().y(), 3.0, 1e-3);
  EXPECT_NEAR(corrected.poses()[6].translation().y(), 3.0, 1e-3);  // after the last: its correction
}

// The gauge: the first keyframe is the run's given start, however strongly a prior pulls at it.
TEST(PoseGraph, HoldsTheFirstKeyframeAtItsGivenPose) {
  PoseGraph graph;
  graph.addKeyframe(0, poseOf(0, 0, 0, 0));
  graph.addKeyframe(10, poseOf(10, 0, 0, 0));
  PosePrior a, b;
  a.pose = poseOf(0, 1, 0, 0.1);
  b.pose = poseOf(10, 1, 0, 0.1);
  a.information = b.information = Eigen::Vector4d(1e6, 1e6, 1e6, 1e6).asDiagonal();
  graph.addPrior(0, a);
  graph.addPrior(1, b);
  graph.addOdometry(0, 1, poseOf(10, 0, 0, 0), Matrix6d::Identity() * 1e-6);
  graph.solve();
  EXPECT_TRUE(graph.pose(0).isApprox(poseOf(0, 0, 0, 0), 1e-12)) << graph.pose(0).matrix();
  EXPECT_NEAR(graph.pose(1).translation().y(), 1.0, 1e-3);  // the second follows its prior
}

TEST(PoseGraph, RejectsBadInput) {
  PoseGraph graph;
  graph.addKeyframe(5, SE3::Identity());
  EXPECT_THROW(graph.addKeyframe(5, SE3::Identity()), Error);
  EXPECT_THROW(graph.addOdometry(0, 1, SE3::Identity(), Matrix6d::Identity()), Error);
  EXPECT_THROW(graph.addPrior(3, PosePrior{}), Error);
  EXPECT_THROW(PoseGraph({.priorHuber = 0.0}), Error);
  EXPECT_THROW(PoseGraph({.maxIterations = 0}), Error);
  EXPECT_THROW(PoseGraph({.mapErrorLength = -1.0}), Error);
}

}  // namespace
}  // namespace hdprior

namespace hdprior {
namespace {

// A straight 100 m drive along x with exact odometry (0.5 % and 0.05 deg sigmas per 2 m step) and a
// lateral prior every keyframe, all `lateralBias` off (one street's drivable area, shifted) with
// `sigmaGivenMap` and a map error of `mapSigma`; returns the mean lateral shift the graph makes.
double meanLateralShift(double mapErrorLength, double lateralBias, double sigmaGivenMap, double mapSigma) {
  PoseGraphOptions o;
  o.mapErrorLength = mapErrorLength;
  PoseGraph graph(o);
  const SE3 step = poseOf(2.0, 0, 0, 0);
  Matrix6d info = Matrix6d::Zero();
  info.diagonal() << 1 / std::pow(0.05 * kDegree, 2), 1 / std::pow(0.05 * kDegree, 2), 1 / std::pow(0.05 * kDegree, 2),
      1 / std::pow(0.01, 2), 1 / std::pow(0.01, 2), 1 / std::pow(0.01, 2);
  const int n = 51;
  for (int k = 0; k < n; ++k) {
    const SE3 truth = poseOf(2.0 * k, 0, 0, 0);
    graph.addKeyframe(int64_t(k) * 100'000'000, truth);
    if (k > 0) graph.addOdometry(size_t(k) - 1, size_t(k), step, info);
    PosePrior p;
    p.pose = poseOf(2.0 * k, lateralBias, 0, 0);
    p.information = Eigen::Vector4d(1.0 / std::pow(0.3 * kDegree, 2), 0.0, 1.0 / std::pow(sigmaGivenMap, 2), 0.0).asDiagonal();
    p.mapSigma = mapSigma;
    graph.addPrior(size_t(k), p);
  }
  graph.solve();
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += graph.pose(size_t(k)).translation().y();
  return sum / n;
}

TEST(PoseGraph, PriorsSharingOneMapErrorDoNotAddUpToCertainty) {
  // Fifty priors 0.2 m off, each 0.05 m given the map, the map 0.2 m: taken as independent they pull
  // the drive most of the way; as one field over 50 m they are a few observations of one offset,
  // and the odometry from the fixed start keeps the drive where it is.
  const double independent = meanLateralShift(0.0, 0.2, 0.05, 0.2);
  const double correlated = meanLateralShift(50.0, 0.2, 0.05, 0.2);
  std::printf("mean lateral shift: independent %.3f m, correlated %.3f m\n", independent, correlated);
  EXPECT_GT(independent, 0.08);
  EXPECT_LT(correlated, 0.5 * independent);
  // Without a map error the two are the same graph.
  EXPECT_NEAR(meanLateralShift(0.0, 0.2, 0.05, 0.0), meanLateralShift(50.0, 0.2, 0.05, 0.0), 1e-6);
}

TEST(PoseGraph, ACorrelatedMapErrorStillLetsThePriorsCorrectADrift) {
  // The odometry drifts 1 deg in yaw over the drive (1.7 m across at its end); the priors are right.
  for (double length : {0.0, 50.0}) {
    PoseGraphOptions o;
    o.mapErrorLength = length;
    PoseGraph graph(o);
    Matrix6d info = Matrix6d::Zero();
    info.diagonal() << 1 / std::pow(0.05 * kDegree, 2), 1 / std::pow(0.05 * kDegree, 2), 1 / std::pow(0.05 * kDegree, 2),
        1 / std::pow(0.02, 2), 1 / std::pow(0.02, 2), 1 / std::pow(0.02, 2);
    const SE3 drifting = poseOf(2.0, 0, 0, 0.02 * kDegree);
    SE3 odometry = SE3::Identity();
    for (int k = 0; k < 51; ++k) {
      if (k > 0) odometry = odometry * drifting;
      graph.addKeyframe(int64_t(k) * 100'000'000, odometry);
      if (k > 0) graph.addOdometry(size_t(k) - 1, size_t(k), drifting, info);
      PosePrior p;
      p.pose = poseOf(2.0 * k, 0, 0, 0);
      p.information = Eigen::Vector4d(1.0 / std::pow(0.3 * kDegree, 2), 0.0, 1.0 / std::pow(0.05, 2), 0.0).asDiagonal();
      p.mapSigma = 0.2;
      graph.addPrior(size_t(k), p);
    }
    const double before = std::abs(odometry.translation().y());
    graph.solve();
    const double after = std::abs(graph.pose(50).translation().y());
    std::printf("map error length %.0f m: end %.3f m across -> %.3f m\n", length, before, after);
    EXPECT_GT(before, 0.4);
    EXPECT_LT(after, 0.25 * before) << length;
  }
}

}  // namespace
}  // namespace hdprior
