// The labelled changes a map check missed, as events the bench can jump to: only those the drive
// passes within 15 m of and no report of their element lies near, each at the sweep nearest to it.
#include "engine/eval/missed_change_events.h"

#include <gtest/gtest.h>

#include "engine/geom/se3.h"

namespace hdprior {
namespace {

TEST(MissedChangeEvents, AChangeNoReportLiesNearIsAnEventAtTheNearestSweep) {
  // A drive along x, a sweep every metre (0.1 s).
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int i = 0; i <= 100; ++i) {
    stamps.push_back(int64_t(i) * 100'000'000);
    poses.push_back(makeSE3(Eigen::Quaterniond::Identity(), {double(i), 0.0, 0.0}));
  }
  const PoseTrajectory drive(stamps, poses);
  MapChangeReport report;
  LaneLineStretch found;
  found.laneId = 4;
  found.side = "left";
  found.line = {{10.0, 2.0}, {20.0, 2.0}};
  found.verdict = MapVerdict::Contradicted;
  report.laneLines = {found};
  const std::vector<MapChangeLabel> labels = {
      {"lane_boundary", "lane_line_moved", 4, {{{10.0, 3.0}, {20.0, 3.0}}}, 3.0},  // reported
      {"lane_boundary", "lane_line_moved", 7, {{{60.0, 3.0}, {70.0, 3.0}}}, 3.0},  // missed, nearest sweep 60
      {"drivable_area", "kerb_moved", 9, {{{15.0, 5.0}, {18.0, 5.0}}}, 5.0},         // a lane report is not an area's
      {"drivable_area", "removed", 11, {{{0.0, 40.0}, {5.0, 40.0}, {5.0, 45.0}}}, 40.0}};  // beyond 15 m: never counted
  const std::vector<RunEvent> events = missedChangeEvents(report, labels, drive, stamps);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, RunEvent::Kind::MissedChange);
  EXPECT_EQ(events[0].frame, 15u);
  EXPECT_EQ(events[0].detail, "kerb_moved drivable_area 9, 5.0 m from the drive, not reported");
  EXPECT_EQ(events[1].frame, 60u);
  EXPECT_EQ(events[1].detail, "lane_line_moved lane_boundary 7, 3.0 m from the drive, not reported");
  EXPECT_TRUE(isFrameEvent(events[0].kind));
  EXPECT_STREQ(toString(events[0].kind), "missed-change");
}

}  // namespace
}  // namespace hdprior
