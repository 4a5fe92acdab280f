// Scan-to-map matching speed and accuracy on the real shared log: the 2-D NDT and PCL's
// NDT on the same road points and curbs (as the pipeline matches them) from the same starts (the truth moved by a lateral offset in
// {-1.5, 0, +1.5} m and a yaw offset in {-3, 0, +3} degrees, for both sweeps), and the
// road-point extraction that feeds them. Counters: mean absolute lateral / along / yaw
// error and the share of starts within 0.25 m lateral and 0.5 degrees.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/match/cost_landscape.h"
#include "engine/match/map_matcher.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

struct Case {
  std::vector<Eigen::Vector2d> points, curbs;
  Eigen::Vector3d truth, start;
};

struct Fixture {
  std::unique_ptr<ArgoverseLog> log;
  std::unique_ptr<HdMap> map;
  std::vector<Case> cases;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture f;
    f.log = std::make_unique<ArgoverseLog>(fs::path(HDPRIOR_SHARED_DATA) / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede");
    HdMapOptions o;
    o.ndtCellSizes = MatchOptions{}.cellSizes;
    f.map = std::make_unique<HdMap>(HdMap::load(f.log->mapFiles(), o));
    for (size_t s = 0; s < f.log->sweepCount(); ++s) {
      const SE3 truth3 = f.log->cityTEgo().at(f.log->sweepTimestamps()[s]);
      const Eigen::Vector3d truth = planarPose(truth3);
      const auto sweep = f.log->sweep(s);
      const PlanarRoadPoints points = sweepRoadPoints(*sweep, levelRotation(truth3), SweepRoadPointOptions{});
      for (double lateral : {-1.5, 0.0, 1.5}) {
        for (double yawDeg : {-3.0, 0.0, 3.0}) {
          f.cases.push_back({points.road, points.curb, truth, offsetPose(truth, {0.0, lateral, yawDeg * kDegree})});
        }
      }
    }
    return f;
  }();
  return f;
}

// Every case with its road points thinned evenly to `count` (the speed target is stated for
// 3,500 road points; the real sweeps give about 4,100).
std::vector<Case> thinnedTo(const std::vector<Case>& cases, size_t count) {
  std::vector<Case> out = cases;
  for (Case& c : out) {
    if (c.points.size() <= count) continue;
    std::vector<Eigen::Vector2d> kept;
    for (size_t i = 0; i < count; ++i) kept.push_back(c.points[i * c.points.size() / count]);
    c.points = std::move(kept);
  }
  return out;
}

void runMatches(benchmark::State& state, MatchBackend backend, size_t pointCap = 0) {
  const Fixture& f = fixture();
  const std::vector<Case> cases = pointCap > 0 ? thinnedTo(f.cases, pointCap) : f.cases;
  MatchOptions o;
  o.backend = backend;
  o.timeBudgetMs = 1e6;  // measure the full match, never cut it
  MapMatcher matcher(*f.map, o);
  size_t i = 0, n = 0, ok = 0;
  double lateral = 0, along = 0, yaw = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ % cases.size()];
    const MatchResult r = matcher.match(c.points, c.start, c.curbs);
    const Eigen::Vector3d e = planarError(c.truth, r.estimate);
    ++n;
    along += std::abs(e.x());
    lateral += std::abs(e.y());
    yaw += std::abs(e.z()) / kDegree;
    ok += std::abs(e.y()) < 0.25 && std::abs(e.z()) < 0.5 * kDegree;
  }
  state.counters["lateral_m"] = lateral / double(n);
  state.counters["along_m"] = along / double(n);
  state.counters["yaw_deg"] = yaw / double(n);
  state.counters["within"] = double(ok) / double(n);
  state.counters["points"] = double(cases.front().points.size());
}

void BM_MatchNdt2d(benchmark::State& state) { runMatches(state, MatchBackend::Ndt2d); }
BENCHMARK(BM_MatchNdt2d)->Unit(benchmark::kMillisecond)->Iterations(90);

// The default matcher on the same starts with 3,500 road points a sweep: the speed target.
void BM_MatchNdt2dAt3500(benchmark::State& state) { runMatches(state, MatchBackend::Ndt2d, 3500); }
BENCHMARK(BM_MatchNdt2dAt3500)->Unit(benchmark::kMillisecond)->Iterations(90);

void BM_MatchPclNdt(benchmark::State& state) { runMatches(state, MatchBackend::PclNdt); }
BENCHMARK(BM_MatchPclNdt)->Unit(benchmark::kMillisecond)->Iterations(18);

void BM_SweepRoadPoints(benchmark::State& state) {
  const Fixture& f = fixture();
  const auto sweep = f.log->sweep(0);
  const Eigen::Matrix3d level = levelRotation(f.log->cityTEgo().at(f.log->sweepTimestamps()[0]));
  SweepRoadPointOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(sweepRoadPoints(*sweep, level, options).road.size());
  state.counters["sweep_points"] = double(sweep->points.size());
}
BENCHMARK(BM_SweepRoadPoints)->Unit(benchmark::kMillisecond);

// The tuning bench's cost landscape: 61 x 61 (x, y) offsets every 0.1 m and 41 yaw offsets, the
// first sweep's road points on the finest grid around the ground truth.
void BM_CostLandscape61(benchmark::State& state) {
  const Fixture& f = fixture();
  const Case& c = f.cases.front();
  const MatchOptions match;
  for (auto _ : state) benchmark::DoNotOptimize(matchLandscape(*f.map, match, c.points, c.truth).scores.data());
  state.counters["points"] = double(c.points.size());
  state.counters["poses"] = 61.0 * 61.0 + 41.0;
}
BENCHMARK(BM_CostLandscape61)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hdprior
