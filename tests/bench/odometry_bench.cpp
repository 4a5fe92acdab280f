// Odometry speed: sweeps per second of Odometry::registerSweep (deskew, features, scan-to-map
// registration, local map update) on ~100k-point sweeps.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "engine/sim/log_writer.h"

namespace {

using namespace hdprior;

// A simulated town drive (Argoverse-like stacked lidar), written once per process to a temp folder.
const std::vector<std::shared_ptr<const LidarSweep>>& simulatedSweeps() {
  static const auto sweeps = [] {
    SimulationOptions o;
    o.townSeed = 3;
    o.seed = 5;
    o.seconds = 10.0;
    o.outDir = std::filesystem::temp_directory_path() / "hdprior_odometry_bench";
    std::filesystem::remove_all(o.outDir);
    const SimulationResult r = simulateLog(o);
    const ArgoverseLog log(r.dir, 1);
    std::vector<std::shared_ptr<const LidarSweep>> out;
    for (size_t i = 0; i < log.sweepCount(); ++i) out.push_back(log.sweep(i));
    std::filesystem::remove_all(o.outDir);
    return out;
  }();
  return sweeps;
}

void BM_OdometrySimulatedDrive(benchmark::State& state) {
  const auto& sweeps = simulatedSweeps();
  size_t points = 0;
  for (const auto& s : sweeps) points += s->points.size();
  OdometryOptions options;
  options.registration.threads = int(state.range(0));
  for (auto _ : state) {
    Odometry odometry(options);
    for (const auto& s : sweeps) benchmark::DoNotOptimize(odometry.registerSweep(*s));
  }
  state.SetItemsProcessed(int64_t(state.iterations() * sweeps.size()));
  state.counters["points_per_sweep"] = double(points) / double(sweeps.size());
  state.counters["sweeps"] = double(sweeps.size());
}
// Rates are per wall-clock second (UseRealTime); the CPU column is the whole process (both threads).
BENCHMARK(BM_OdometrySimulatedDrive)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(2)
    ->UseRealTime()->MeasureProcessCPUTime();

// The two real Argoverse 2 sweeps (99k points each), fed alternately with advancing timestamps:
// every call after the first runs the full pipeline against a populated local map.
void BM_OdometryRealSweeps(benchmark::State& state) {
  const ArgoverseLog log(std::filesystem::path(HDPRIOR_SHARED_DATA) / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede");
  LidarSweep a = *log.sweep(0), b = *log.sweep(1);
  Odometry odometry;
  odometry.registerSweep(a);
  int64_t t = b.timestampNs;
  bool useB = true;
  for (auto _ : state) {
    LidarSweep& s = useB ? b : a;
    s.timestampNs = t;
    benchmark::DoNotOptimize(odometry.registerSweep(s));
    t += 100'000'000;
    useB = !useB;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OdometryRealSweeps)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

}  // namespace
