// Acceptance on the real shared log: matching the sweep's road points and curbs (as the pipeline and
// `hdprior match` do) to the drivable area from a grid of start offsets around the ground-truth pose.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
#include "test_data.h"

namespace hdprior {
namespace {

struct GridOutcome {
  int starts = 0, converged = 0;
  double maxAlong = 0, sumAlong = 0, maxLateral = 0, maxYawDeg = 0;
};

GridOutcome runGrid(MatchBackend backend, size_t sweepIndex, bool print) {
  const ArgoverseLog log(test::sharedLog());
  MatchOptions options;
  options.backend = backend;
  options.timeBudgetMs = 1000.0;
  HdMapOptions mapOptions;
  mapOptions.ndtCellSizes = options.cellSizes;
  const HdMap map = HdMap::load(log.mapFiles(), mapOptions);
  const SE3 truth3 = log.cityTEgo().at(log.sweepTimestamps()[sweepIndex]);
  const Eigen::Vector3d truth = planarPose(truth3);
  const auto sweep = log.sweep(sweepIndex);
  const PlanarRoadPoints points = sweepRoadPoints(*sweep, levelRotation(truth3), SweepRoadPointOptions{});
  MapMatcher matcher(map, options);
  GridOutcome g;
  for (double along : {-1.0, 0.0, 1.0}) {
    for (double lateral : {-1.5, -0.75, 0.0, 0.75, 1.5}) {
      for (double yawDeg : {-3.0, 0.0, 3.0}) {
        const Eigen::Vector3d start = offsetPose(truth, {along, lateral, yawDeg * kDegree});
        const MatchResult r = matcher.match(points.road, start, points.curb);
        const Eigen::Vector3d e = planarError(truth, r.estimate);
        const bool ok = std::abs(e.y()) < 0.25 && std::abs(e.z()) < 0.5 * kDegree;
        ++g.starts;
        g.converged += ok;
        g.maxAlong = std::max(g.maxAlong, std::abs(e.x()));
        g.sumAlong += std::abs(e.x());
        g.maxLateral = std::max(g.maxLateral, std::abs(e.y()));
        g.maxYawDeg = std::max(g.maxYawDeg, std::abs(e.z()) / kDegree);
        if (print) {
          std::printf("start (%+.2f %+.2f %+.1f deg) -> error along %+.3f lateral %+.3f yaw %+.3f deg, %s %s, iters %d, "
                      "%.2f ms, inliers %.2f, score/pt %.3f, eig %.1f %.1f %.1f\n",
                      along, lateral, yawDeg, e.x(), e.y(), e.z() / kDegree, toString(r.status), r.reason.c_str(),
                      r.iterations, r.timeMs, r.inlierRatio, r.scorePerPoint, r.eigenvalues(0), r.eigenvalues(1),
                      r.eigenvalues(2));
        }
      }
    }
  }
  std::printf("%s sweep %zu, %zu road points, %zu curb points: %d / %d starts within 0.25 m lateral and 0.5 deg; along-road error mean %.3f "
              "max %.3f m; max lateral %.3f m, max yaw %.3f deg\n",
              backend == MatchBackend::Ndt2d ? "ndt2d" : "pcl", sweepIndex, points.road.size(), points.curb.size(), g.converged, g.starts,
              g.sumAlong / g.starts, g.maxAlong, g.maxLateral, g.maxYawDeg);
  return g;
}

TEST(RealMatch, Ndt2dConvergesFromNinetyPercentOfStarts) {
  for (size_t s = 0; s < 2; ++s) {
    const GridOutcome g = runGrid(MatchBackend::Ndt2d, s, true);
    EXPECT_GE(g.converged, int(std::ceil(0.9 * g.starts)));
  }
}

}  // namespace
}  // namespace hdprior
