// The cost landscape of simulated keyframes (a procedural-town drive through the Session): at a
// keyframe on a straight street (the match degenerate along it) it is a ridge along the road. (At
// this drive's first junction the landscape's maximum lies 3 m from the converged match, with either
// NDT lookup: the road points there fit the map better off the truth; docs/experiments/2026-12-01-bilinear-lookup.md. The maximum
// at the result is tested on a synthetic intersection in cost_landscape_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <unistd.h>

#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/match/cost_landscape.h"
#include "engine/match/map_matcher.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/session.h"
#include "engine/sim/log_writer.h"
#include "test_data.h"

namespace hdprior {
namespace {

struct SimulatedDrive {
  std::unique_ptr<ArgoverseLog> log;
  std::unique_ptr<HdMap> map;
  std::unique_ptr<Session> session;
  Config config;
};

// A 6 s town drive, run once per process with the matcher untimed (a busy machine must not
// change which keyframes are accepted).
const SimulatedDrive& drive() {
  static const SimulatedDrive d = [] {
    SimulatedDrive d;
    SimulationOptions sim;
    sim.townSeed = 2;
    sim.seed = 3;
    sim.seconds = 6.0;
    sim.outDir = test::processOutputDir("cost_landscape_sim");
    d.log = std::make_unique<ArgoverseLog>(simulateLog(sim).dir);
    d.config.match.timeBudgetMs = 1e6;
    d.map = loadPriorMap(*d.log, d.config);
    d.session = std::make_unique<Session>(*d.log, d.map.get(), d.config);
    d.session->run();
    return d;
  }();
  return d;
}

// The first keyframe whose run-time match has this status, inspected again.
// The first keyframe whose drivable boundary, near its road points, constrains all three directions
// (a junction) or leaves one free (a straight street): the boundary constraint's eigenvalues.
std::optional<KeyframeInspection> firstWhereBoundaryObserves(bool all) {
  const SimulatedDrive& d = drive();
  const MatchOptions& o = d.config.match;
  for (const KeyframeMatch& m : d.session->matches()) {
    const Eigen::Vector3d& e = m.match.eigenvalues;
    if (e.maxCoeff() <= 0.0) continue;
    const bool free = e.minCoeff() < o.degenerateRatio * e.maxCoeff() || e.minCoeff() < o.minBoundaryPoints;
    if (free != all) return d.session->inspectKeyframe(m.keyframe, d.config.roadPoints, d.config.match);
  }
  return std::nullopt;
}

// The landscape's range along a line through its centre in direction `heading` (cells nearest to it).
double rangeAlong(const CostLandscape& l, double heading) {
  double lo = 1e300, hi = -1e300;
  const double half = l.offset(l.size - 1);
  for (double t = -half; t <= half + 1e-9; t += l.options.step) {
    const int col = l.size / 2 + int(std::lround(t * std::cos(heading) / l.options.step));
    const int row = l.size / 2 + int(std::lround(t * std::sin(heading) / l.options.step));
    if (col < 0 || row < 0 || col >= l.size || row >= l.size) continue;
    lo = std::min(lo, l.at(row, col));
    hi = std::max(hi, l.at(row, col));
  }
  return hi - lo;
}

TEST(CostLandscapeSim, IsARidgeAlongAStraightStreet) {
  const std::optional<KeyframeInspection> corridor = firstWhereBoundaryObserves(false);
  const std::optional<KeyframeInspection> junction = firstWhereBoundaryObserves(true);
  ASSERT_TRUE(corridor && junction) << "the drive needs a keyframe on a straight street and one at a junction";
  const auto ratio = [](const KeyframeInspection& k) {
    const CostLandscape l = matchLandscape(*drive().map, drive().config.match, k.roadPoints, k.match.estimate);
    const double heading = k.match.estimate.z();  // the vehicle drives along the road
    return rangeAlong(l, heading) / rangeAlong(l, heading + M_PI / 2);
  };
  const double straight = ratio(*corridor), crossing = ratio(*junction);
  std::printf("along / across variation: %.3f on the straight street (keyframe %zu), %.3f at keyframe %zu\n", straight,
              corridor->keyframe, crossing, junction->keyframe);
  // 0.114 since the road points follow the camber out to the kerbs (a ridge all the same: the score
  // varies nine times less along the street than across it).
  EXPECT_LT(straight, 0.15);
  EXPECT_GT(crossing, 0.3);  // the measure tells them apart
}

}  // namespace
}  // namespace hdprior
