// Lane lines judged by the paint runs beside them: on the line, beside it, too near to tell, in a
// crossing; a boundary two lanes share is one line; unpainted boundaries are not read.
#include "engine/changes/lane_line_check.h"

#include <gtest/gtest.h>

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

// Two lanes along x from 0 to 25 m: the dashed line between them at y = 0 (the first lane's left,
// the second's right, drawn the other way), a solid line on the first lane's right (y = -3.5), the
// second lane's left boundary unpainted (y = 3.5).
VectorMap twoLanes() {
  LaneSegment a, b;
  a.id = 1, b.id = 2;
  a.leftLaneBoundary = {{0, 0, 0}, {25, 0, 0}};
  a.leftLaneMarkType = "DASHED_WHITE";
  a.rightLaneBoundary = {{0, -3.5, 0}, {25, -3.5, 0}};
  a.rightLaneMarkType = "SOLID_WHITE";
  b.rightLaneBoundary = {{25, 0, 0}, {0, 0, 0}};
  b.rightLaneMarkType = "DASHED_WHITE";
  b.leftLaneBoundary = {{25, 3.5, 0}, {0, 3.5, 0}};
  b.leftLaneMarkType = "NONE";
  VectorMap map;
  map.laneSegments = {a, b};
  return map;
}

// Paint runs along y = `y` from x0 to x1 every half metre, in the sweep of a sensor at (x0, 0).
SweepPaint runsAlong(double y, double x0, double x1) {
  SweepPaint paint;
  for (double x = x0; x <= x1; x += 0.5) paint.runs.push_back({{x - x0, y}, 4});
  return paint;
}

SE3 at(double x) {
  SE3 pose = SE3::Identity();
  pose.translation().x() = x;
  return pose;
}

TEST(LaneLineCheck, ASharedLineIsOneLineCutIntoStretchesAndUnpaintedOnesAreNotRead) {
  LaneLineEvidence evidence(twoLanes(), ChangeOptions{});
  evidence.add(0, runsAlong(0.05, 0.0, 7.5), at(0.0));
  evidence.add(1, runsAlong(0.05, 12.0, 19.5), at(12.0));
  evidence.add(2, runsAlong(3.5, 22.0, 24.5), at(22.0));  // on the unpainted boundary: read as nothing's
  const std::vector<LaneLineStretch> s = evidence.stretches();
  ASSERT_EQ(s.size(), 2u) << "stretches 0 and 1 of the one white line: the third saw no run";
  for (const LaneLineStretch& x : s) {
    EXPECT_EQ(x.laneId, 1);
    EXPECT_EQ(x.side, "left");
    EXPECT_EQ(x.markType, "DASHED_WHITE");
    EXPECT_EQ(x.verdict, MapVerdict::Consistent);
  }
  EXPECT_EQ(s[0].index, 0);
  EXPECT_EQ(s[1].index, 1);
  EXPECT_EQ(s[0].bestFrame, 0);
  EXPECT_EQ(s[1].bestFrame, 1);
}

// The dashed line's paint 1.2 m to its left while the solid line's is on it: the map drew the
// dashed line in the wrong place. All paint 1.2 m off: the pose is, and the sweep is left out.
// So is a sweep that sees one line, all of it beside it.
TEST(LaneLineCheck, PaintBesideOneLineAndNoneOnItContradictsIt) {
  LaneLineEvidence evidence(twoLanes(), ChangeOptions{});
  SweepPaint paint = runsAlong(1.2, 0.0, 6.5);  // every run within 8 m of the sensor
  const SweepPaint solid = runsAlong(-3.45, 0.0, 6.5);
  paint.runs.insert(paint.runs.end(), solid.runs.begin(), solid.runs.end());
  evidence.add(4, paint, at(0.0));
  std::vector<LaneLineStretch> s = evidence.stretches();
  ASSERT_EQ(s.size(), 2u);
  const LaneLineStretch& dashed = s[0].markType == "DASHED_WHITE" ? s[0] : s[1];
  const LaneLineStretch& solidLine = s[0].markType == "DASHED_WHITE" ? s[1] : s[0];
  EXPECT_EQ(solidLine.verdict, MapVerdict::Consistent);
  EXPECT_EQ(dashed.verdict, MapVerdict::Contradicted);
  EXPECT_NEAR(dashed.offset, 1.2, 0.15) << "to the line's left (it runs along +x)";
  EXPECT_EQ(dashed.runsOnLine, 0);
  EXPECT_EQ(dashed.runsAtOffset, 14);
  EXPECT_GT(dashed.confidence, 0.9);
  EXPECT_EQ(dashed.bestFrame, 4);
  EXPECT_EQ(evidence.misalignedFrames(), 0);

  LaneLineEvidence shifted(twoLanes(), ChangeOptions{});
  SweepPaint both = runsAlong(1.2, 0.0, 6.5);
  const SweepPaint solidShifted = runsAlong(-2.3, 0.0, 6.5);
  both.runs.insert(both.runs.end(), solidShifted.runs.begin(), solidShifted.runs.end());
  shifted.add(0, both, at(0.0));
  EXPECT_TRUE(shifted.stretches().empty());
  EXPECT_EQ(shifted.misalignedFrames(), 1);

  // One line's paint beside it, more runs than the other line shows on it: a restriping moves one
  // line, a pose error every line in view, so the sweep counts. Alone in view, it cannot tell.
  LaneLineEvidence restriped(twoLanes(), ChangeOptions{});
  SweepPaint most = runsAlong(1.2, 0.0, 6.5);
  const SweepPaint glimpse = runsAlong(-3.45, 0.0, 1.0);
  most.runs.insert(most.runs.end(), glimpse.runs.begin(), glimpse.runs.end());
  restriped.add(0, most, at(0.0));
  EXPECT_EQ(restriped.misalignedFrames(), 0);
  restriped.add(1, runsAlong(1.2, 0.0, 6.5), at(0.0));
  EXPECT_EQ(restriped.misalignedFrames(), 1);
}

TEST(LaneLineCheck, PaintHalfAMetreOffOrBesideARunOnTheLineDoesNotContradictIt) {
  LaneLineEvidence nearby(twoLanes(), ChangeOptions{});
  nearby.add(0, runsAlong(-0.6, 0.0, 7.5), at(0.0));  // a pose half a metre off
  ASSERT_EQ(nearby.stretches().size(), 1u);
  EXPECT_EQ(nearby.stretches()[0].verdict, MapVerdict::Unobserved);

  LaneLineEvidence both(twoLanes(), ChangeOptions{});
  SweepPaint paint;
  paint.runs = {{{1.0, 1.2}, 4}, {{2.0, 1.2}, 4}, {{3.0, 0.1}, 4}};
  both.add(0, paint, at(0.0));
  ASSERT_EQ(both.stretches().size(), 1u);
  EXPECT_EQ(both.stretches()[0].verdict, MapVerdict::Consistent);
}

TEST(LaneLineCheck, PaintInACrossingAndBeyondTheRangeIsNotTheLines) {
  VectorMap map = twoLanes();
  PedestrianCrossing c;
  c.id = 9;
  c.edge1 = {{2, -3.5, 0}, {2, 3.5, 0}};
  c.edge2 = {{5, -3.5, 0}, {5, 3.5, 0}};
  map.pedestrianCrossings = {c};
  LaneLineEvidence evidence(map, ChangeOptions{});
  evidence.add(0, runsAlong(1.2, 1.5, 5.5), at(1.5));   // within the crossing grown by a metre
  SweepPaint far;  // beside the line 9-12 m ahead: farther than paint shows
  for (double x = 9.0; x <= 12.0; x += 0.5) far.runs.push_back({{x, 1.2}, 4});
  evidence.add(1, far, at(0.0));
  EXPECT_TRUE(evidence.stretches().empty());
}

}  // namespace
}  // namespace hdprior
