// The real sweeps' kerbs on the real map: at the true pose they lie on its boundaries; with the pose
// moved sideways they meet the map only under the opposite shift, and the check would leave the sweep out.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/changes/sweep_alignment.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/config.h"
#include "test_data.h"

namespace hdprior {
namespace {

// The shared log's map (without NDT grids) and, for each of its sweeps, the sweep labelled at its
// true pose and its alignment at any pose.
struct RealSweeps {
  ArgoverseLog log{test::sharedLog()};
  HdMap map = HdMap::load(log.mapFiles(), [] {
    HdMapOptions o;
    o.ndtCellSizes.clear();
    return o;
  }());
  SE3 truth(size_t i) const { return log.cityTEgo().at(log.sweepTimestamps()[i]); }
  LabelledSweep labelled(size_t i) const { return labelSweep(*log.sweep(i), levelRotation(truth(i)), defaultConfig().roadPoints); }
  SweepAlignment at(const LabelledSweep& sweep, const SE3& pose) const {
    return sweepAlignment(sweep, pose, map.boundaryDistance(), map.vectorMap().drivableAreas, &map.groundHeight(), ChangeOptions{});
  }
};

TEST(SweepAlignmentReal, TheKerbsLieOnTheMapAtTheTruePoseAndMeetItShiftedBackFromAMovedOne) {
  const RealSweeps real;
  const ChangeOptions o;
  for (size_t i = 0; i < real.log.sweepCount(); ++i) {
    const SE3 truth = real.truth(i);
    const LabelledSweep sweep = real.labelled(i);
    const SweepAlignment a = real.at(sweep, truth);
    SE3 moved = truth;
    moved.translation() += truth.linear() * Eigen::Vector3d(0.0, 2.5, 0.0);
    const SweepAlignment m = real.at(sweep, moved);
    std::printf("sweep %zu: %d kerb points, %d on the map at the true pose (best shift %.2f m: %d); moved 2.5 m left: %d on it, "
                "%d shifted (%.2f, %.2f) on %d polygons\n",
                i, a.kerbs, a.alignedAtPose, a.shift.norm(), a.alignedShifted, m.alignedAtPose, m.alignedShifted, m.shift.x(),
                m.shift.y(), m.polygonsShifted);
    EXPECT_GE(a.alignedAtPose, 0.75 * a.kerbs);  // measured 22 of 26 and 20 of 25
    EXPECT_FALSE(a.misaligned(o, 1000.0));
    EXPECT_TRUE(m.misaligned(o, 1000.0));
    EXPECT_FALSE(m.misaligned(o, 50.0)) << "after 50 m a pose is not 2.5 m off: that is the map";
    EXPECT_NEAR(m.shift.y(), -2.5, 0.5);
  }
}

// At the true pose the road under the car lies on the ground-height raster; raised by 0.4 m (or
// lowered), the pose is off and the sweep is left out, kerbs or not.
TEST(SweepAlignmentReal, TheRoadUnderTheCarLiesOnTheRasterAtTheTruePose) {
  const RealSweeps real;
  const ChangeOptions o;
  for (size_t i = 0; i < real.log.sweepCount(); ++i) {
    const LabelledSweep sweep = real.labelled(i);
    const auto at = [&](double dz) {
      SE3 pose = real.truth(i);
      pose.translation().z() += dz;
      return real.at(sweep, pose);
    };
    const SweepAlignment a = at(0.0);
    std::printf("sweep %zu: %d road points within 10 m on the raster, %.3f m over it\n", i, a.roadOnRaster, a.roadOverRaster);
    EXPECT_GT(a.roadOnRaster, 1000);
    EXPECT_LT(std::abs(a.roadOverRaster), 0.1);
    EXPECT_FALSE(a.offGround(o));
    EXPECT_FALSE(a.misaligned(o, 1000.0));
    for (double dz : {0.4, -0.4}) {
      const SweepAlignment off = at(dz);
      EXPECT_NEAR(off.roadOverRaster, a.roadOverRaster + dz, 1e-6);
      EXPECT_TRUE(off.offGround(o));
      EXPECT_TRUE(off.misaligned(o, 0.0)) << "a height off the raster needs no drive to be a pose error";
    }
  }
}

}  // namespace
}  // namespace hdprior
