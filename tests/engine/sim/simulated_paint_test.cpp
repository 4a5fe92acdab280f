// A family's road surface against the real sweep's (PaintReal): faint, worn paint and bright
// asphalt patches, so that the paint reading meets in the simulator what it meets on real roads.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/sim/log_writer.h"
#include "paint_statistics.h"
#include "test_data.h"

namespace hdprior {
namespace {

TEST(SimulatedPaint, AFamilysPaintAndAsphaltAreWithinAFactorOfTwoOfTheRealSweeps) {
  for (auto [town, seed] : {std::pair<uint64_t, uint64_t>{101, 1001}, {202, 2002}}) {
    SimulationOptions o;
    o.townSeed = town;
    o.seconds = 1.0;
    o.seed = seed;
    o.family = seed < 2000 ? SceneFamily::Tuning : SceneFamily::Validation;
    o.outDir = test::freshOutputDir("simulated_paint");
    const SimulationResult r = simulateLog(o);
    const test::PaintStatistics s = test::paintStatistics(r.dir, 2, 5);
    std::printf("seed %llu: %zu sweeps; on a painted line %.3f of %ld returns bright, asphalt %.3f of %ld; paint runs a "
                "sweep: %.1f on lines, %.1f elsewhere\n",
                (unsigned long long)seed, s.sweeps, s.onLineBrightShare(), s.onLine, s.asphaltBrightShare(), s.asphalt,
                s.runsOnLinesPerSweep(), s.runsElsewherePerSweep());
    ASSERT_EQ(s.sweeps, 5u);
    ASSERT_GT(s.onLine, 100);
    // The real sweep: 0.28, 0.134, 14 runs off the lines a sweep.
    EXPECT_GT(s.onLineBrightShare(), 0.28 / 2);
    EXPECT_LT(s.onLineBrightShare(), 0.28 * 2);
    EXPECT_GT(s.asphaltBrightShare(), 0.134 / 4) << "the flecks of real asphalt are mostly single returns; the patches are runs";
    EXPECT_LT(s.asphaltBrightShare(), 0.134 * 2);
    EXPECT_GT(s.runsElsewherePerSweep(), 13.0 / 2);
    EXPECT_LT(s.runsElsewherePerSweep(), 13.0 * 2);
  }
}

}  // namespace
}  // namespace hdprior
