// Headless snapshot speed on llvmpipe: a 1280x720 picture of the shared log with all layers
// (target < 300 ms). Context creation, layer set-up and the map load are outside the timed
// loop; each iteration uploads a new sweep (alternating frames), draws and reads back.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "render/png_writer.h"
#include "render/snapshot.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

const fs::path kLog = fs::path(HDPRIOR_SHARED_DATA) / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede";

void snapshotBench(benchmark::State& state, render::View view) {
  const ArgoverseLog log(kLog);
  const HdMap map = HdMap::load(log.mapFiles(), render::renderMapOptions());
  render::Snapshotter snapshotter(log, map, {1280, 720, view, {}});
  for (size_t frame : {0, 1}) snapshotter.render(frame);  // sweeps into the log's cache
  size_t frame = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(snapshotter.render(frame).rgba.data());
    frame ^= 1;
  }
}

void BM_Snapshot1280x720AllLayersTop(benchmark::State& state) { snapshotBench(state, render::View::Top); }
void BM_Snapshot1280x720AllLayersOrbit(benchmark::State& state) { snapshotBench(state, render::View::Orbit); }

// The same with PNG encoding and the atomic write, as `hdprior snapshot` does it.
void BM_Snapshot1280x720WithPng(benchmark::State& state) {
  const ArgoverseLog log(kLog);
  const HdMap map = HdMap::load(log.mapFiles(), render::renderMapOptions());
  render::Snapshotter snapshotter(log, map, {1280, 720, render::View::Top, {}});
  const fs::path out = fs::temp_directory_path() / "hdprior_snapshot_bench.png";
  size_t frame = 0;
  for (auto _ : state) {
    render::writePng(out, snapshotter.render(frame));
    frame ^= 1;
  }
  fs::remove(out);
}

BENCHMARK(BM_Snapshot1280x720AllLayersTop)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Snapshot1280x720AllLayersOrbit)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Snapshot1280x720WithPng)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hdprior
