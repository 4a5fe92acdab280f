// Lane lines judged by the painted cells beside them against the asphalt's share: paint on the
// line, beside it, too near to tell, too little to tell, in a crossing; a line is judged whole; a
// boundary two lanes share is one line; unpainted boundaries are not read; a sweep whose paint is
// beside every line is off its pose.
#include "engine/changes/lane_line_check.h"

#include <gtest/gtest.h>

namespace hdprior {
namespace {

constexpr double kAsphalt = 0.05;  // the log's share of painted cells off the map's paint

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

SE3 at(double x) {
  SE3 pose = SE3::Identity();
  pose.translation().x() = x;
  return pose;
}

// The road within 7 m ahead of a sensor, from y = -5.5 to 5.5, a point in every 0.25 m cell, and
// paint runs in every cell along y = `y` for each y of `lines` (ego frame: the sensor at the origin).
SweepPaint sweep(std::initializer_list<double> lines, double length = 7.0) {
  SweepPaint paint;
  for (double x = 0.125; x < length; x += 0.25)
    for (double y = -5.375; y < 5.5; y += 0.25) paint.road.push_back({x, y});
  for (double y : lines)
    for (double x = 0.125; x < length; x += 0.25) paint.runs.push_back({{x, y}, 4});
  return paint;
}

// Sweeps every 7 m from x = 0 to 21: the whole 25 m of road ahead seen once.
void drive(LaneLineEvidence& evidence, std::initializer_list<double> lines) {
  for (int k = 0; k < 4; ++k) evidence.add(k, sweep(lines, k == 3 ? 4.0 : 7.0), at(7.0 * k));
}

const LaneLineStretch& ofLine(const std::vector<LaneLineStretch>& s, const std::string& mark) {
  for (const LaneLineStretch& x : s)
    if (x.markType == mark) return x;
  throw std::runtime_error("no stretch of " + mark);
}

TEST(LaneLineCheck, PaintOnTheLinesMakesThemConsistentAndASharedLineIsOneLine) {
  LaneLineEvidence evidence(twoLanes(), ChangeOptions{});
  drive(evidence, {0.1, -3.4});
  const std::vector<LaneLineStretch> s = evidence.stretches(kAsphalt);
  ASSERT_EQ(s.size(), 6u) << "three stretches of each painted line; the unpainted boundary is not read";
  int dashed = 0;
  for (const LaneLineStretch& x : s) {
    EXPECT_EQ(x.laneId, 1);
    EXPECT_EQ(x.verdict, MapVerdict::Consistent) << x.markType << " " << x.index;
    EXPECT_GT(x.confidence, 0.99);
    EXPECT_GT(x.onLine.painted, 0.4 * x.onLine.road) << "the whole line's: its paint fills one of the two bins";
    if (x.markType != "DASHED_WHITE") continue;
    EXPECT_EQ(x.side, "left");
    EXPECT_EQ(x.index, dashed++);
  }
  EXPECT_EQ(dashed, 3);
  EXPECT_EQ(s[0].bestFrame, 0);
  EXPECT_EQ(ofLine(s, "DASHED_WHITE").asphaltShare, kAsphalt);
}

// The dashed line's paint 1.1 m to its left while the solid line's is on it: the map drew the
// dashed line in the wrong place, over its whole length. All paint 1.1 m off: the pose is, and the
// sweep is left out. So is a sweep that sees one line, all of it beside it.
TEST(LaneLineCheck, PaintBesideOneLineAndNoneOnItContradictsTheWholeLine) {
  LaneLineEvidence evidence(twoLanes(), ChangeOptions{});
  drive(evidence, {1.1, -3.45});
  const std::vector<LaneLineStretch> s = evidence.stretches(kAsphalt);
  EXPECT_EQ(ofLine(s, "SOLID_WHITE").verdict, MapVerdict::Consistent);
  int contradicted = 0;
  for (const LaneLineStretch& x : s) {
    if (x.markType != "DASHED_WHITE") continue;
    ++contradicted;
    EXPECT_EQ(x.verdict, MapVerdict::Contradicted);
    EXPECT_NEAR(x.offset, 1.1, 0.15) << "to the line's left (it runs along +x)";
    EXPECT_EQ(x.onLine.painted, 0);
    EXPECT_GT(x.atOffset.painted, 40);
    EXPECT_GT(x.confidence, 0.9);
  }
  EXPECT_EQ(contradicted, 3);
  EXPECT_EQ(evidence.misalignedFrames(), 0);

  LaneLineEvidence shifted(twoLanes(), ChangeOptions{});
  drive(shifted, {1.1, -2.4});
  EXPECT_TRUE(shifted.stretches(kAsphalt).empty());
  EXPECT_EQ(shifted.misalignedFrames(), 4);

  // One line's paint beside it, more runs than the other line shows on it: a restriping moves one
  // line, a pose error every line in view, so the sweep counts. Alone in view, it cannot tell.
  LaneLineEvidence restriped(twoLanes(), ChangeOptions{});
  SweepPaint most = sweep({1.1});
  for (double x = 0.125; x < 2.0; x += 0.25) most.runs.push_back({{x, -3.45}, 4});
  restriped.add(0, most, at(0.0));
  EXPECT_EQ(restriped.misalignedFrames(), 0);
  restriped.add(1, sweep({1.1}), at(0.0));
  EXPECT_EQ(restriped.misalignedFrames(), 1);
}

// Paint a third of a metre off (a pose error) neither contradicts a line nor shows it; paint on the
// line and beside it is the line's; a few painted cells are too few to tell paint from asphalt.
TEST(LaneLineCheck, PaintNearTheLineOrBesideItsOwnPaintOrTooLittleDoesNotContradictIt) {
  LaneLineEvidence nearby(twoLanes(), ChangeOptions{});
  drive(nearby, {-0.35, -3.45});
  EXPECT_EQ(ofLine(nearby.stretches(kAsphalt), "DASHED_WHITE").verdict, MapVerdict::Unobserved);

  LaneLineEvidence both(twoLanes(), ChangeOptions{});
  drive(both, {1.1, 0.05, -3.45});
  EXPECT_EQ(ofLine(both.stretches(kAsphalt), "DASHED_WHITE").verdict, MapVerdict::Consistent);

  LaneLineEvidence glimpse(twoLanes(), ChangeOptions{});
  SweepPaint few = sweep({});
  for (double x : {1.125, 3.125}) few.runs.push_back({{x, 1.1}, 4});
  glimpse.add(0, few, at(0.0));
  const std::vector<LaneLineStretch> s = glimpse.stretches(kAsphalt);
  for (const LaneLineStretch& x : s) EXPECT_EQ(x.verdict, MapVerdict::Unobserved) << x.markType;
  EXPECT_FALSE(s.empty());
}

TEST(LaneLineCheck, PaintInACrossingAndBeyondTheRangeIsNotTheLines) {
  VectorMap map = twoLanes();
  PedestrianCrossing c;
  c.id = 9;
  c.edge1 = {{2, -3.5, 0}, {2, 3.5, 0}};
  c.edge2 = {{5, -3.5, 0}, {5, 3.5, 0}};
  map.pedestrianCrossings = {c};
  LaneLineEvidence evidence(map, ChangeOptions{});
  SweepPaint inCrossing;  // within the crossing grown by a metre
  for (double x = 1.125; x < 6.0; x += 0.25)
    for (double y = -5.375; y < 5.5; y += 0.25) inCrossing.road.push_back({x, y}), inCrossing.runs.push_back({{x, y}, 4});
  evidence.add(0, inCrossing, at(0.0));
  SweepPaint far = sweep({1.1});  // 9-12 m ahead of the sensor: farther than paint shows
  for (Eigen::Vector2d& p : far.road) p.x() += 9.0;
  for (PaintRun& r : far.runs) r.centre.x() += 9.0;
  evidence.add(1, far, at(0.0));
  EXPECT_TRUE(evidence.stretches(kAsphalt).empty());
}

}  // namespace
}  // namespace hdprior
