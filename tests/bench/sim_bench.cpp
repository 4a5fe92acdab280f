// Simulator speed: rays per second through the ray caster, one ~100k-point sweep, the
// scene build, and a whole simulated log written with 2 threads (the figure per sweep
// extrapolates to the 600-sweep, 60 s drive; target under 3 minutes on 2 cores).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <numbers>

#include "engine/map/lane_graph.h"
#include "engine/sim/lidar_model.h"
#include "engine/sim/log_writer.h"
#include "engine/sim/ray_caster.h"
#include "engine/sim/scene_builder.h"
#include "engine/sim/sweep_simulator.h"
#include "engine/sim/town_generator.h"
#include "engine/sim/trajectory.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

// A town (seed 7), a 20 s route on it and the scene around the route.
struct Fixture {
  TownMap town = generateTown(TownOptions{}, 7);
  GroundHeight ground = GroundHeight::fromNpy(town.groundHeight, town.imgSim2City, "town");
  LaneGraph lanes{town.vectorMap, {}, "town"};
  PoseTrajectory route = routeTrajectory(lanes, ground, RouteOptions{}, 1);
  std::vector<Eigen::Vector2d> path() const {
    std::vector<Eigen::Vector2d> p;
    for (const SE3& T : route.poses()) p.push_back(T.translation().head<2>());
    return p;
  }
  Scene scene = buildScene(town.vectorMap, ground, lanes, path(), route.startNs(), {}, 1, "town");
  LidarModel lidar = argoverseLikeLidar();
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_CastRaysOfOneSweep(benchmark::State& state) {
  const Fixture& f = fixture();
  const SE3 cityTSensor = f.route.at(f.route.startNs() + 5'000'000'000) * f.lidar.units[0].egoTSensor;
  std::vector<Eigen::Vector3d> dirs;
  for (int c = 0; c < f.lidar.azimuthSteps; ++c)
    for (const LidarUnit& u : f.lidar.units)
      for (double el : u.elevations) {
        const double az = 2 * std::numbers::pi * c / f.lidar.azimuthSteps;
        const double e = u.egoTSensor.linear()(2, 2) < 0 ? -el : el;
        dirs.push_back(cityTSensor.linear() * Eigen::Vector3d(std::cos(e) * std::cos(az), std::cos(e) * std::sin(az), std::sin(e)));
      }
  size_t hits = 0;
  for (auto _ : state)
    for (const Eigen::Vector3d& d : dirs) hits += castRay(f.scene, {}, cityTSensor.translation(), d, 200.0).has_value();
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(dirs.size()));
  state.counters["rays"] = double(dirs.size());
}
BENCHMARK(BM_CastRaysOfOneSweep)->Unit(benchmark::kMillisecond);

void BM_SimulateOneSweep(benchmark::State& state) {
  const Fixture& f = fixture();
  size_t points = 0;
  int64_t k = 0;
  for (auto _ : state) {
    ++k;
    const SimulatedSweep s = simulateSweep(f.scene, f.lidar, f.route, f.route.startNs() + (k % 150) * 100'000'000,
                                           SweepNoise{}, uint64_t(k));
    points = s.sweep.points.size();
  }
  state.counters["points"] = double(points);
}
BENCHMARK(BM_SimulateOneSweep)->Unit(benchmark::kMillisecond);

void BM_BuildScene(benchmark::State& state) {
  const Fixture& f = fixture();
  const auto path = f.path();
  for (auto _ : state) {
    const Scene s = buildScene(f.town.vectorMap, f.ground, f.lanes, path, f.route.startNs(), {}, 1, "town");
    benchmark::DoNotOptimize(s.boxes().size());
  }
}
BENCHMARK(BM_BuildScene)->Unit(benchmark::kMillisecond);

// The whole `hdprior sim --town 7 --seconds N` (town, route, scene, sweeps, LZ4 files) on
// 2 threads; "per_sweep" is the wall time per sweep, x600 for a 60 s drive.
void BM_SimulateTownLog(benchmark::State& state) {
  const fs::path out = fs::temp_directory_path() / "hdprior_sim_bench";
  SimulationOptions o;
  o.townSeed = 7;
  o.seconds = double(state.range(0));
  o.outDir = out;
  o.threads = 2;
  size_t sweeps = 0;
  for (auto _ : state) sweeps = simulateLog(o).sweeps;
  fs::remove_all(out);
  state.counters["sweeps"] = double(sweeps);
  state.counters["per_sweep"] =
      benchmark::Counter(double(sweeps) * double(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SimulateTownLog)->Arg(10)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace hdprior
