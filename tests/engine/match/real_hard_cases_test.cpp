// Harder cases made from the shared real sweeps (issue 16): one side's kerb hidden, the road points
// beyond 20 m removed, the sweep cut to a 90 degree sector ahead. From the 45 starts of the acceptance
// grid each match must be accurate (within 0.25 m lateral and 0.5 deg) or honest: rejected, or its
// lateral and yaw errors within 3 reported sigma (a direction reported unobservable is honest).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "engine/eval/match_calibration.h"
#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
#include "test_data.h"

namespace hdprior {
namespace {

using Keep = std::function<bool(const Eigen::Vector2d&)>;

std::vector<Eigen::Vector2d> kept(const std::vector<Eigen::Vector2d>& points, const Keep& keep) {
  std::vector<Eigen::Vector2d> out;
  for (const Eigen::Vector2d& p : points)
    if (keep(p)) out.push_back(p);
  return out;
}

struct CaseOutcome {
  int starts = 0, accurate = 0, honest = 0, rejected = 0;
};

CaseOutcome runCase(const HdMap& map, const ArgoverseLog& log, size_t sweepIndex, const char* name, const Keep& keep) {
  MatchOptions options;
  options.timeBudgetMs = 1000.0;
  MapMatcher matcher(map, options);
  const SE3 truth3 = log.cityTEgo().at(log.sweepTimestamps()[sweepIndex]);
  const Eigen::Vector3d truth = planarPose(truth3);
  const auto sweep = log.sweep(sweepIndex);
  const PlanarRoadPoints all = sweepRoadPoints(*sweep, levelRotation(truth3), SweepRoadPointOptions{});
  const std::vector<Eigen::Vector2d> road = kept(all.road, keep), curb = kept(all.curb, keep);
  CaseOutcome c;
  double maxLateral = 0, maxYaw = 0;
  for (double along : {-1.0, 0.0, 1.0}) {
    for (double lateral : {-1.5, -0.75, 0.0, 0.75, 1.5}) {
      for (double yawDeg : {-3.0, 0.0, 3.0}) {
        const MatchResult r = matcher.match(road, offsetPose(truth, {along, lateral, yawDeg * kDegree}), curb);
        const MatchErrorSample s = matchErrorSample(truth, r.estimate, r.information);
        const bool accurate = std::abs(s.error(1)) < 0.25 && std::abs(s.error(2)) < 0.5 * kDegree;
        const bool covered = !(std::abs(s.error(1)) > 3.0 * s.sigma(1)) && !(std::abs(s.error(2)) > 3.0 * s.sigma(2));
        const bool rejected = r.status == MatchStatus::Rejected;
        ++c.starts;
        c.accurate += accurate && !rejected;
        c.rejected += rejected;
        c.honest += accurate || rejected || covered;
        if (!rejected) {
          maxLateral = std::max(maxLateral, std::abs(s.error(1)));
          maxYaw = std::max(maxYaw, std::abs(s.error(2)) / kDegree);
        }
        if (!(accurate || rejected || covered)) {
          std::printf("  %s sweep %zu start (%+.1f %+.2f %+.0f deg): error lateral %+.3f yaw %+.3f deg, sigma %.3f m %.3f deg, %s\n",
                      name, sweepIndex, along, lateral, yawDeg, s.error(1), s.error(2) / kDegree, s.sigma(1), s.sigma(2) / kDegree,
                      toString(r.status));
        }
      }
    }
  }
  std::printf("%s, sweep %zu (%zu road, %zu curb points): %d / %d accurate or honest (%d accurate, %d rejected); "
              "used matches: max lateral %.3f m, max yaw %.3f deg\n",
              name, sweepIndex, road.size(), curb.size(), c.honest, c.starts, c.accurate, c.rejected, maxLateral, maxYaw);
  return c;
}

TEST(RealHardCases, EveryCaseIsAccurateOrHonestFromNinetyFivePercentOfStarts) {
  const ArgoverseLog log(test::sharedLog());
  HdMapOptions mapOptions;
  mapOptions.ndtCellSizes = MatchOptions{}.cellSizes;
  const HdMap map = HdMap::load(log.mapFiles(), mapOptions);
  const std::vector<std::pair<const char*, Keep>> cases = {
      {"left kerb hidden (y > 2 m removed)", [](const Eigen::Vector2d& p) { return p.y() <= 2.0; }},
      {"right kerb hidden (y < -2 m removed)", [](const Eigen::Vector2d& p) { return p.y() >= -2.0; }},
      {"points beyond 20 m removed", [](const Eigen::Vector2d& p) { return p.norm() <= 20.0; }},
      {"90 deg sector ahead", [](const Eigen::Vector2d& p) { return std::abs(std::atan2(p.y(), p.x())) <= 45.0 * kDegree; }},
  };
  for (const auto& [name, keep] : cases) {
    for (size_t s = 0; s < 2; ++s) {
      const CaseOutcome c = runCase(map, log, s, name, keep);
      EXPECT_GE(c.honest, int(std::ceil(0.95 * c.starts))) << name << ", sweep " << s;
    }
  }
}

}  // namespace
}  // namespace hdprior
