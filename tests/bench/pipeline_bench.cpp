// The full pipeline's speed (issue target: 20 sweeps/s on 2 cores with ~100k-point sweeps):
// odometry + road points + scan-to-map matching + incremental pose graph, as `hdprior run` runs it,
// sweeps read from disk. The global map rebuilt afterwards is not included (it is not online work).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "engine/io/argoverse_log.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/sim/log_writer.h"

namespace {

using namespace hdprior;

// A simulated 10 s town drive (Argoverse-like stacked lidar), written once per process.
const std::filesystem::path& simulatedLog() {
  static const std::filesystem::path dir = [] {
    SimulationOptions o;
    o.townSeed = 3;
    o.seed = 5;
    o.seconds = 10.0;
    o.outDir = std::filesystem::temp_directory_path() / "hdprior_pipeline_bench";
    std::filesystem::remove_all(o.outDir);
    return simulateLog(o).dir;
  }();
  return dir;
}

void BM_Pipeline(benchmark::State& state) {
  const ArgoverseLog log(simulatedLog());
  const bool priors = state.range(0) != 0;
  StageTimes times;
  size_t sweeps = 0;
  for (auto _ : state) {
    const PipelineRun run = runPipeline(log, Config{}, {.priors = priors});
    sweeps += run.estimate.size();
    times = run.times;
    state.SetIterationTime(run.times.pipelineS);
  }
  state.SetItemsProcessed(int64_t(sweeps));
  const double n = double(sweeps) / double(state.iterations());
  state.counters["odometry_ms"] = 1e3 * times.odometryS / n;
  state.counters["road_points_ms"] = 1e3 * times.roadPointsS / n;
  state.counters["match_ms"] = 1e3 * times.matchS / n;
  state.counters["graph_ms"] = 1e3 * times.graphS / n;
}
// Per sweep: items_per_second is sweeps per second of the pipeline proper (manual time).
BENCHMARK(BM_Pipeline)->ArgName("priors")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(2)->UseManualTime();

}  // namespace
