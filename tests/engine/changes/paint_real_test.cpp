// What the paint reading sees on the real sweeps: faint lane paint on bright-flecked asphalt. The
// simulator's road surface is drawn around these figures (SimulatedPaint below, docs/simulator.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "paint_statistics.h"
#include "test_data.h"

namespace hdprior {
namespace {

TEST(PaintReal, LanePaintIsFaintAndAsphaltIsFleckedWithinEightMetres) {
  const test::PaintStatistics s = test::paintStatistics(test::sharedLog(), 1, 2);
  std::printf("real: %zu sweeps; on a painted line %.3f of %ld returns bright, asphalt %.3f of %ld; paint runs a sweep: "
              "%.1f on lines, %.1f elsewhere\n",
              s.sweeps, s.onLineBrightShare(), s.onLine, s.asphaltBrightShare(), s.asphalt, s.runsOnLinesPerSweep(),
              s.runsElsewherePerSweep());
  ASSERT_EQ(s.sweeps, 2u);
  EXPECT_NEAR(s.onLineBrightShare(), 0.28, 0.05);  // measured 0.282 of 124
  EXPECT_NEAR(s.asphaltBrightShare(), 0.134, 0.02);  // measured 0.134 of 5,026
  EXPECT_NEAR(s.runsOnLinesPerSweep(), 2.5, 1.0);
  EXPECT_NEAR(s.runsElsewherePerSweep(), 14.0, 3.0);  // measured 13.0 against the sweep's median, 14.0 against each ring's
  // Paint is brighter than asphalt, but not by much: a run lies off the lines 5 times as often as on them.
  EXPECT_GT(s.onLineBrightShare(), 1.5 * s.asphaltBrightShare());
  EXPECT_GT(s.runsElsewherePerSweep(), 3.0 * s.runsOnLinesPerSweep());
}

// The runs off the lines are things on the road, not noise: the second sweep (7 cm on) finds them
// again where the first did, so a drive sees them sweep after sweep (the simulator's patches are
// fixed in the world for this reason).
TEST(PaintReal, RunsOffTheLinesRepeatFromSweepToSweep) {
  const std::vector<std::vector<Eigen::Vector2d>> runs = test::paintStatistics(test::sharedLog(), 1, 2).elsewhere;
  ASSERT_EQ(runs.size(), 2u);
  int again = 0;
  for (const Eigen::Vector2d& a : runs[1])
    again += std::any_of(runs[0].begin(), runs[0].end(), [&](const Eigen::Vector2d& b) { return (a - b).norm() <= 0.2; });
  std::printf("runs off the lines: %zu and %zu; %d of the second sweep's within 0.2 m of one of the first's\n", runs[0].size(),
              runs[1].size(), again);
  ASSERT_GE(runs[1].size(), 10u);  // measured 11 and 15; 14 again
  EXPECT_GE(again, int(0.8 * double(runs[1].size())));
}

}  // namespace
}  // namespace hdprior
