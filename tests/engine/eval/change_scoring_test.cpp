// A map check's reports scored against a simulated log's labels, per element: a report is right
// within 5 m of a labelled change of its element, a change counts for recall when the drive passes
// within 15 m of it, and a lane line with several contradicted stretches is one report.
#include "engine/eval/change_scoring.h"

#include <gtest/gtest.h>

namespace hdprior {
namespace {

using Line = std::vector<Eigen::Vector2d>;

LaneLineStretch laneStretch(int64_t lane, const char* side, double x0, double y, MapVerdict verdict) {
  LaneLineStretch s;
  s.laneId = lane;
  s.side = side;
  s.line = {{x0, y}, {x0 + 10.0, y}};
  s.verdict = verdict;
  return s;
}

MapChangeLabel label(const char* element, const char* change, Line place, double routeDistance) {
  return {element, change, 1, {std::move(place)}, routeDistance};
}

TEST(ChangeScoring, ALaneLineIsOneReportHoweverManyOfItsStretchesAreContradicted) {
  MapChangeReport report;
  report.drivenKm = 0.5;
  // Lane 7's right line: two stretches contradicted near the restriped line, one consistent.
  report.laneLines = {laneStretch(7, "right", 0.0, 0.0, MapVerdict::Contradicted),
                      laneStretch(7, "right", 10.0, 0.0, MapVerdict::Contradicted),
                      laneStretch(7, "right", 20.0, 0.0, MapVerdict::Consistent),
                      // Lane 9's left line, 40 m away from every change: a false alarm.
                      laneStretch(9, "left", 0.0, 40.0, MapVerdict::Contradicted)};
  const std::vector<MapChangeLabel> labels = {
      label("lane_boundary", "lane_line_moved", {{0.0, 1.0}, {20.0, 1.0}}, 2.0),
      label("lane_boundary", "lane_line_moved", {{0.0, -100.0}, {20.0, -100.0}}, 30.0),  // the drive never passes near
      label("drivable_area", "narrowed", {{0.0, 40.0}, {10.0, 40.0}}, 2.0)};              // another element's change
  const ChangeScore s = scoreMapChanges(report, labels, MapElement::LaneBoundary);
  EXPECT_EQ(s.reports, 2u);
  EXPECT_EQ(s.reportsNearChange, 1u);
  EXPECT_EQ(s.changes, 1u);
  EXPECT_EQ(s.changesFound, 1u);
  EXPECT_EQ(s.falseAlarms(), 1u);
  EXPECT_DOUBLE_EQ(s.drivenKm, 0.5);
}

TEST(ChangeScoring, ADrivableAreaIsRightWhereItsContradictedStretchesLieAndAMissingSurfaceByItsOutline) {
  MapChangeReport report;
  BoundaryStretch far, near;
  far.areaId = near.areaId = 3;
  far.line = {{100.0, 0.0}, {110.0, 0.0}};
  near.line = {{0.0, 0.0}, {10.0, 0.0}};
  far.verdict = MapVerdict::Consistent;
  near.verdict = MapVerdict::Contradicted;
  report.stretches = {far, near};
  report.drivableAreas = {{3, MapVerdict::Contradicted, 0.9, 0, 0}};
  MissingSurface missing;
  missing.outline = {{50.0, 50.0}, {60.0, 50.0}, {60.0, 60.0}, {50.0, 60.0}};
  report.missing = {missing};
  // The removed polygon contains the missing surface's first vertex; the kerb moved 4 m from the
  // contradicted stretch.
  const std::vector<MapChangeLabel> labels = {
      label("drivable_area", "removed", {{45.0, 45.0}, {70.0, 45.0}, {70.0, 70.0}, {45.0, 70.0}}, 5.0),
      label("drivable_area", "kerb_moved", {{0.0, 4.0}, {10.0, 4.0}}, 3.0),
      label("drivable_area", "shifted", {{200.0, 200.0}, {210.0, 200.0}, {210.0, 210.0}}, 12.0)};
  const ChangeScore s = scoreMapChanges(report, labels, MapElement::DrivableArea);
  EXPECT_EQ(s.reports, 2u);
  EXPECT_EQ(s.reportsNearChange, 2u);
  EXPECT_EQ(s.changes, 3u);
  EXPECT_EQ(s.changesFound, 2u);
  EXPECT_DOUBLE_EQ(s.recall(), 2.0 / 3.0);
}

}  // namespace
}  // namespace hdprior
