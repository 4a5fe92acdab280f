// The map check's speed (issue target: `hdprior changes` on a 30 s log within 5 s after the run):
// the map loaded as the command loads it, then a sweep every 2 m labelled into the evidence grid (two
// at a time) and every boundary read, along the log's poses (the run's would cost the same).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "engine/changes/map_change_report.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/config.h"
#include "engine/sim/log_writer.h"

namespace {

using namespace hdprior;

// A simulated 30 s town drive over a map 30 % stale near the route, written once per process.
const std::filesystem::path& simulatedLog() {
  static const std::filesystem::path dir = [] {
    SimulationOptions o;
    o.townSeed = 3;
    o.seed = 5;
    o.seconds = 30.0;
    o.mapChange = 0.3;
    o.mapChangeWithin = 15.0;
    o.outDir = std::filesystem::temp_directory_path() / "hdprior_changes_bench";
    std::filesystem::remove_all(o.outDir);
    return simulateLog(o).dir;
  }();
  return dir;
}

void BM_MapCheck(benchmark::State& state) {
  const ArgoverseLog log(simulatedLog());
  const PoseTrajectory poses = log.cityTEgoAtSweeps();
  const Config config;
  size_t frames = 0;
  for (auto _ : state) {
    const std::unique_ptr<HdMap> map = loadCheckedMap(log, poses, config.roadPoints, ChangeOptions{});
    frames = detectMapChanges(log, *map, poses, config.roadPoints, ChangeOptions{}).frames;
  }
  state.counters["sweeps_checked"] = double(frames);
  state.counters["log_s"] = 30.0;
}
BENCHMARK(BM_MapCheck)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
