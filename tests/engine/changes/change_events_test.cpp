// The map check's events: a lane line is judged whole, so its contradicted stretches are one event
// at the line's best frame; consistent lines and stretches never seen are none.
#include "engine/changes/change_events.h"

#include <gtest/gtest.h>

namespace hdprior {
namespace {

LaneLineStretch stretchOf(int64_t lane, const std::string& side, int index, MapVerdict verdict, int bestFrame) {
  LaneLineStretch s;
  s.laneId = lane;
  s.side = side;
  s.index = index;
  s.verdict = verdict;
  s.bestFrame = bestFrame;
  s.offset = -1.2;
  s.confidence = 0.9;
  s.onLine = {400, 12};
  s.atOffset = {300, 40};
  return s;
}

TEST(ChangeEvents, AContradictedLaneLineIsOneEventAtItsBestFrame) {
  MapChangeReport report;
  report.laneLines = {stretchOf(7, "right", 0, MapVerdict::Contradicted, 40), stretchOf(7, "right", 1, MapVerdict::Contradicted, 40),
                      stretchOf(7, "right", 2, MapVerdict::Contradicted, 40), stretchOf(7, "left", 0, MapVerdict::Consistent, 12),
                      stretchOf(9, "left", 0, MapVerdict::Contradicted, -1)};
  const std::vector<RunEvent> events = mapChangeEvents(report);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, RunEvent::Kind::MapChange);
  EXPECT_EQ(events[0].frame, 40u);
  EXPECT_EQ(events[0].detail,
            "lane 7 right line: paint 1.2 m to its right (40 of 300 road cells), as little on it as on the asphalt (12 of 400; confidence 0.90)");
}

// A contradicted drivable area says what its most confident stretch saw: a kerb off its boundary,
// road going on across a gap to the next polygon, or the whole polygon off its kerbs.
TEST(ChangeEvents, AContradictedDrivableAreaSaysWhatItsSurestStretchSaw) {
  MapChangeReport report;
  report.drivableAreas = {{3, MapVerdict::Contradicted, 0.8, 0, 12}, {4, MapVerdict::Contradicted, 0.7, 0, 20},
                          {5, MapVerdict::Contradicted, 0.9, 0, 30}};
  BoundaryStretch kerb, gap, shifted;
  kerb.areaId = 3, kerb.verdict = MapVerdict::Contradicted, kerb.offset = 2.1, kerb.confidence = 0.8, kerb.evidence = "road_beyond_boundary";
  gap.areaId = 4, gap.verdict = MapVerdict::Contradicted, gap.offset = 2.5, gap.confidence = 0.7, gap.evidence = "road_across_gap";
  shifted.areaId = 5, shifted.verdict = MapVerdict::Contradicted, shifted.offset = -0.9, shifted.confidence = 0.9;
  shifted.evidence = "polygon_offset", shifted.polygonShift = {0.6, -0.8};
  report.stretches = {kerb, gap, gap, shifted, shifted, shifted};
  const std::vector<RunEvent> events = mapChangeEvents(report);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].detail, "drivable area 3: kerb 2.1 m outside its boundary, 1 stretch (confidence 0.80)");
  EXPECT_EQ(events[1].detail, "drivable area 4: road across a 2.5 m gap to the next area, 2 stretches (confidence 0.70)");
  EXPECT_EQ(events[1].frame, 20u);
  EXPECT_EQ(events[2].detail, "drivable area 5: the whole area 1.0 m off its kerbs (they lie x +0.6, y -0.8 m from it), 3 stretches (confidence 0.90)");
}

TEST(ChangeEvents, SweepsLeftOutOneAfterAnotherAreOneEventAtTheFirst) {
  MapChangeReport report;
  SweepAlignment a;
  a.kerbs = 31, a.alignedAtPose = 1, a.alignedShifted = 12, a.shift = {0.0, 4.0};
  report.misaligned = {{263, a, false}, {266, a, true}, {269, a, true}, {300, a, false}};
  const std::vector<RunEvent> events = mapChangeEvents(report);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, RunEvent::Kind::MisalignedSweeps);
  EXPECT_EQ(events[0].frame, 263u);
  EXPECT_EQ(events[0].detail,
            "sweeps 263-269 left out (3 read): their kerbs meet the map shifted 4.0 m (first: 12 of 31 kerb points, 1 unshifted); the poses look off");
  EXPECT_EQ(events[1].frame, 300u);
  EXPECT_EQ(events[1].detail, "sweep 300 left out: its kerbs meet the map shifted 4.0 m (12 of 31 kerb points, 1 unshifted); its pose looks off");
  EXPECT_TRUE(isMapCheckEvent(events[0].kind));
  EXPECT_TRUE(isFrameEvent(events[0].kind));
}

}  // namespace
}  // namespace hdprior
