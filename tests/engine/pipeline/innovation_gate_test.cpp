#include "engine/pipeline/innovation_gate.h"

#include <gtest/gtest.h>

#include <vector>

#include "../geom/forward_step.h"
#include "engine/geom/angles.h"

namespace hdprior {
namespace {

Matrix6d stepInformation() {
  Eigen::Matrix<double, 6, 1> v;
  v << 0.1 * kDegree, 0.1 * kDegree, 0.1 * kDegree, 0.01, 0.01, 0.01;
  return v.cwiseAbs2().cwiseInverse().asDiagonal();
}

using test::forward;

// A lateral prior (y observed, sigma 0.1 m) at (x, y), heading +x.
PosePrior lateralPrior(double x, double y) {
  PosePrior p;
  p.pose.translation() = Eigen::Vector3d(x, y, 0.0);
  p.information(2, 2) = 1.0 / (0.1 * 0.1);  // order yaw, x, y, z
  return p;
}

// A straight drive of 2 m keyframes. The graph's pose at keyframe k is (2k, graphY(k)); the prior at
// k says y = priorY(k). Returns each keyframe's verdict (keyframe 0 is the start, no prior).
// `outsidePrediction(k)`: the matcher found prior k outside its fixed prediction gate.
std::vector<InnovationGate::Verdict> drive(int keyframes, int reanchorPriors, double (*graphY)(int), double (*priorY)(int),
                                           bool (*outsidePrediction)(int) = nullptr) {
  InnovationGate gate(Eigen::Vector3d::Zero(), 0.0, 0.99, reanchorPriors);
  std::vector<InnovationGate::Verdict> verdicts(1);
  for (int k = 1; k < keyframes; ++k) {
    gate.predict(Eigen::Vector3d(2.0 * (k - 1), graphY(k - 1), 0.0), forward(2.0), stepInformation());
    verdicts.push_back(gate.judge(size_t(k), lateralPrior(2.0 * k, priorY(k)), outsidePrediction && outsidePrediction(k)));
  }
  return verdicts;
}

// The odometry slips 2 m sideways after keyframe 4 and the graph, with every prior gated, stays there.
double slipAfterFour(int k) { return k >= 5 ? 2.0 : 0.0; }
double onTheRoad(int) { return 0.0; }

TEST(InnovationGate, AgreeingPriorsOutvoteAPredictionThatSlipped) {
  const auto v = drive(12, 3, slipAfterFour, onTheRoad);
  for (int k = 1; k <= 5; ++k) EXPECT_TRUE(v[k].admitted) << k;
  // Keyframes 6 and 7 are gated (the prediction is 2 m off, 20 sigma); the third of the run agrees
  // with them and all three go in.
  EXPECT_FALSE(v[6].admitted);
  EXPECT_GT(v[6].chi2, 100.0);
  EXPECT_FALSE(v[7].admitted);
  EXPECT_TRUE(v[8].admitted);
  EXPECT_EQ(v[8].reanchored, (std::vector<size_t>{6, 7}));
}

TEST(InnovationGate, WithoutReanchoringTheSlipShutsEveryPriorOut) {
  const auto v = drive(12, 0, slipAfterFour, onTheRoad);
  for (int k = 6; k < 12; ++k) EXPECT_FALSE(v[k].admitted) << k;
}

// Priors the matcher found outside its fixed prediction gate never go in alone, even where the
// gate's own prediction would take them; a run of them that agree goes in as any gated run.
bool fromSixOn(int k) { return k >= 6; }

TEST(InnovationGate, PriorsOutsideThePredictionGoInOnlyAsARun) {
  const auto v = drive(12, 3, onTheRoad, onTheRoad, fromSixOn);
  for (int k = 1; k <= 5; ++k) EXPECT_TRUE(v[k].admitted) << k;
  EXPECT_FALSE(v[6].admitted);
  EXPECT_LT(v[6].chi2, v[6].quantile);
  EXPECT_FALSE(v[7].admitted);
  EXPECT_TRUE(v[8].admitted);
  EXPECT_EQ(v[8].reanchored, (std::vector<size_t>{6, 7}));
  EXPECT_TRUE(drive(12, 0, onTheRoad, onTheRoad, fromSixOn)[8].admitted == false);
}

// Wrong priors that disagree with one another (a plateau the Newton path wanders along) never form a run.
double wandering(int k) { return k < 6 ? 0.0 : (k % 2 ? 2.0 : -2.0); }

TEST(InnovationGate, PriorsThatDisagreeWithOneAnotherStayOut) {
  const auto v = drive(16, 3, onTheRoad, wandering);
  for (int k = 6; k < 16; ++k) {
    EXPECT_FALSE(v[k].admitted) << k;
    EXPECT_TRUE(v[k].reanchored.empty());
  }
}

// A polygon shifted 2 m sideways under the car: the priors say so from the first keyframe, where
// the odometry cannot have drifted 2 m (1 % of the 2 m driven is one sigma).
double shiftedFromTheStart(int) { return 2.0; }

TEST(InnovationGate, PriorsThatDisagreeWithTheOdometryFromTheStartNeverReanchor) {
  const auto v = drive(40, 3, onTheRoad, shiftedFromTheStart);
  for (int k = 1; k < 40; ++k) {
    EXPECT_FALSE(v[k].admitted) << k;
    EXPECT_TRUE(v[k].reanchored.empty()) << k;
    EXPECT_EQ(v[k].beyondOdometryReach, k >= 3) << k;  // from the third, the run is judged and refused
  }
}

// The same 2 m after 120 m of straight odometry is within what it could have drifted (1.2 m one
// sigma): the run re-anchors. After 20 m (0.2 m) it is not, however long the run goes on.
double shiftedAfter120m(int k) { return k >= 60 ? 2.0 : 0.0; }
double shiftedAfter20m(int k) { return k >= 10 ? 2.0 : 0.0; }

TEST(InnovationGate, ARunReanchorsOnlyWhereTheOdometryCouldHaveDriftedThatFar) {
  const auto late = drive(70, 3, onTheRoad, shiftedAfter120m);
  EXPECT_FALSE(late[60].admitted);
  EXPECT_FALSE(late[61].admitted);
  EXPECT_TRUE(late[62].admitted);
  EXPECT_EQ(late[62].reanchored, (std::vector<size_t>{60, 61}));
  // (Within 40 keyframes: later the gate's own prediction, grown by 60 m without a prior, takes 2 m.)
  const auto early = drive(40, 3, onTheRoad, shiftedAfter20m);
  for (int k = 10; k < 40; ++k) EXPECT_FALSE(early[k].admitted) << k;
}

// A polygon shifted 4 m from 20 m on, with every eighth prior farther still: the run breaks off
// and starts again, by 130 m where the odometry could have drifted 4 m. Nothing has been let in
// since 20 m, so each new run keeps the reach of the first gated prior and stays out.
double shiftedAfter20mBrokenRuns(int k) { return k < 10 ? 0.0 : k % 8 == 0 ? 8.0 : 4.0; }

TEST(InnovationGate, RunsThatStartAgainKeepTheReachOfTheFirstGatedPrior) {
  const auto v = drive(80, 3, onTheRoad, shiftedAfter20mBrokenRuns);
  for (int k = 10; k < 80; ++k) {
    EXPECT_FALSE(v[k].admitted) << k;
    EXPECT_TRUE(v[k].reanchored.empty()) << k;
  }
}

// The same polygon shifted 2 m from 20 m on, and at 120 m one prior on the road that fixes one
// direction only (the tests' priors are lateral). It is let in, but one combination agreeing says
// too little to count the reach again from there: the run after it stays out, where the drive's
// 120 m would have reached 2 m.
double shiftedAfter20mButOneAt120m(int k) { return k >= 10 && k != 60 ? 2.0 : 0.0; }

TEST(InnovationGate, APriorThatFixesOneDirectionDoesNotRestartTheReach) {
  const auto v = drive(80, 3, onTheRoad, shiftedAfter20mButOneAt120m);
  EXPECT_TRUE(v[60].admitted);
  for (int k = 61; k < 80; ++k) {
    EXPECT_FALSE(v[k].admitted) << k;
    EXPECT_TRUE(v[k].reanchored.empty()) << k;
  }
}

}  // namespace
}  // namespace hdprior
