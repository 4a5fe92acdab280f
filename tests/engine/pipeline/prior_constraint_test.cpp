// What a prior constrains (the directions of the vehicle frame its information fixes), the summary
// line, and the run events built from keyframe diagnostics.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "engine/match/match_result.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/prior_constraint.h"
#include "engine/pipeline/run_events.h"

namespace hdprior {
namespace {

// Information over city (x, y, yaw) that fixes `lateral` and `yaw` but nothing along a heading `yaw0`.
Eigen::Matrix3d lateralAndYaw(double yaw0) {
  const Eigen::Vector2d left = Eigen::Rotation2Dd(yaw0) * Eigen::Vector2d(0, 1);
  Eigen::Matrix3d info = Eigen::Matrix3d::Zero();
  info.topLeftCorner<2, 2>() = 100.0 * left * left.transpose();
  info(2, 2) = 400.0;
  return info;
}

TEST(PriorConstraint, NamesTheDirectionsOfTheHeadingFrameItFixes) {
  const double yaw0 = 30.0 * std::numbers::pi / 180.0;
  const Eigen::Vector3d pose(5, 7, yaw0);
  EXPECT_EQ(fixedDirections(Eigen::Matrix3d::Identity() * 50.0, pose).category(), "full");
  EXPECT_EQ(fixedDirections(lateralAndYaw(yaw0), pose).category(), "lateral + yaw");
  Eigen::Matrix3d yawOnly = Eigen::Matrix3d::Zero();
  yawOnly(2, 2) = 100.0;
  EXPECT_EQ(fixedDirections(yawOnly, pose).category(), "yaw");
  // The same information seen from a heading 90 degrees off fixes along instead of lateral.
  EXPECT_EQ(fixedDirections(lateralAndYaw(yaw0), Eigen::Vector3d(5, 7, yaw0 + std::numbers::pi / 2)).category(), "along + yaw");
}

TEST(PriorConstraint, RejectedAndGatedCarryTheirReasonAndFigures) {
  MatchResult rejected;
  rejected.status = MatchStatus::Rejected;
  rejected.reason = "inlier ratio 0.61 < 0.85";
  EXPECT_EQ(constraintOf(rejected).label(), "rejected: inlier ratio 0.61 < 0.85");

  KeyframeMatch gated;
  gated.match.status = MatchStatus::Degenerate;
  gated.match.information = lateralAndYaw(0.0);
  gated.gated = true;
  gated.innovationChi2 = 14.23;
  gated.gateQuantile = 9.21;
  EXPECT_EQ(constraintOf(gated).label(), "gated: chi2 14.2 > 9.2");
  KeyframeMatch outside = gated;
  outside.outsidePrediction = true;
  outside.match.gateChi2 = 15.61;
  EXPECT_EQ(constraintOf(outside).label(), "gated: outside the prediction: chi2 15.6");
  KeyframeMatch beyondReach = outside;
  beyondReach.beyondOdometryReach = true;
  EXPECT_EQ(constraintOf(beyondReach).label(), "gated: chi2 14.2 > 9.2, its run beyond the odometry's reach");
  EXPECT_TRUE(constraintOf(gated).lateral);

  const std::vector<PriorConstraint> all = {fixedDirections(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
                                            fixedDirections(lateralAndYaw(0.0), Eigen::Vector3d::Zero()),
                                            fixedDirections(lateralAndYaw(0.0), Eigen::Vector3d::Zero()),
                                            constraintOf(rejected), constraintOf(gated)};
  EXPECT_EQ(constraintSummary(all), "1 full, 2 lateral + yaw, 1 gated, 1 rejected");
  EXPECT_EQ(constraintSummary({}), "none");
}

KeyframeDiagnostic row(size_t k, PriorConstraint c) {
  KeyframeDiagnostic d;
  d.keyframe = k;
  d.frame = 3 * k;
  d.constraint = std::move(c);
  return d;
}

TEST(RunEvents, RejectedGatedChangesBeyondThreeSigmaAndSkippedSweepsInFrameOrder) {
  const PriorConstraint full = fixedDirections(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  const PriorConstraint partial = fixedDirections(lateralAndYaw(0.0), Eigen::Vector3d::Zero());
  std::vector<KeyframeDiagnostic> rows = {row(0, full), row(1, full), row(2, partial),
                                          row(3, {.kind = PriorConstraint::Kind::Rejected, .reason = "no observable direction"}),
                                          row(4, partial), row(5, {.kind = PriorConstraint::Kind::Gated, .reason = "chi2 20.0 > 9.2"}),
                                          row(6, full)};
  rows[4][DiagnosticField::PriorErrorLateral] = -0.5;  // 0.5 m off with a 0.1 m sigma
  rows[4][DiagnosticField::SigmaLateral] = 0.1;
  rows[1][DiagnosticField::PriorErrorLateral] = 0.25;  // within 3 sigma
  rows[1][DiagnosticField::SigmaLateral] = 0.1;
  const std::vector<SkippedSweep> skipped = {{.index = 10, .file = "10.feather", .problem = "truncated"}};
  const std::vector<RunEvent> events = runEvents(rows, skipped);
  std::vector<std::string> lines;
  for (size_t i = 0; i < events.size(); ++i) lines.push_back(eventLine(i, events[i]));
  const std::vector<std::string> expected = {
      "event 0 keyframe 2 frame 6 constraint-change full -> lateral + yaw",
      "event 1 keyframe 3 frame 9 rejected no observable direction",
      "event 2 keyframe 3 frame 10 skipped-sweep truncated",
      "event 3 keyframe 4 frame 12 beyond-3-sigma lateral 0.5 m > 3 x 0.1 m",
      "event 4 keyframe 5 frame 15 gated chi2 20.0 > 9.2",
      "event 5 keyframe 6 frame 18 constraint-change lateral + yaw -> full"};
  EXPECT_EQ(lines, expected);
}

}  // namespace
}  // namespace hdprior
