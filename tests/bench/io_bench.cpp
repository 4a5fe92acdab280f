// Log I/O speed: opening a 1,000-sweep log, reading a real 100k-point sweep, parsing the map.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "engine/io/argoverse_log.h"
#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "engine/io/npy.h"
#include "engine/io/vector_map.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

const fs::path kLog = fs::path(HDPRIOR_SHARED_DATA) / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede";

// A log with the real poses, calibration and map and 1,000 sweep files (hard links to the
// two real sweeps, so the folder costs no disk space).
fs::path thousandSweepLog() {
  const fs::path dir = fs::temp_directory_path() / "hdprior_bench_1000_sweeps" / "log";
  if (fs::exists(dir / "sensors" / "lidar")) return dir;
  fs::remove_all(dir.parent_path());
  fs::create_directories(dir / "sensors" / "lidar");
  fs::copy(kLog / "map", dir / "map", fs::copy_options::recursive);
  fs::copy(kLog / "calibration", dir / "calibration", fs::copy_options::recursive);
  fs::copy_file(kLog / "city_SE3_egovehicle.feather", dir / "city_SE3_egovehicle.feather");
  const fs::path real = kLog / "sensors" / "lidar" / "315966265259836000.feather";
  for (int i = 0; i < 1000; ++i) {
    const fs::path link = dir / "sensors" / "lidar" / (std::to_string(315966254000000000 + int64_t(i) * 100000000) + ".feather");
    std::error_code ec;
    fs::create_hard_link(real, link, ec);
    if (ec) fs::copy_file(real, link);
  }
  return dir;
}

void BM_OpenLog1000Sweeps(benchmark::State& state) {
  const fs::path dir = thousandSweepLog();
  for (auto _ : state) {
    ArgoverseLog log(dir);
    benchmark::DoNotOptimize(log.sweepCount());
  }
}
BENCHMARK(BM_OpenLog1000Sweeps)->Unit(benchmark::kMillisecond);

void BM_ReadRealSweep(benchmark::State& state) {
  const fs::path path = kLog / "sensors" / "lidar" / "315966265259836000.feather";
  for (auto _ : state) benchmark::DoNotOptimize(readLidarSweep(path).points.size());
  state.SetItemsProcessed(state.iterations() * 99229);
}
BENCHMARK(BM_ReadRealSweep)->Unit(benchmark::kMillisecond);

void BM_ReadSweepFileBytes(benchmark::State& state) {
  const fs::path path = kLog / "sensors" / "lidar" / "315966265259836000.feather";
  for (auto _ : state) benchmark::DoNotOptimize(readFileBytes(path).size());
}
BENCHMARK(BM_ReadSweepFileBytes)->Unit(benchmark::kMillisecond);

void BM_ParseSweepFeather(benchmark::State& state) {
  const std::vector<uint8_t> bytes = readFileBytes(kLog / "sensors" / "lidar" / "315966265259836000.feather");
  for (auto _ : state) benchmark::DoNotOptimize(arrow::parseFeather(bytes, "sweep").numRows);
}
BENCHMARK(BM_ParseSweepFeather)->Unit(benchmark::kMillisecond);

void BM_ReadVectorMap(benchmark::State& state) {
  const ArgoverseLog log(kLog);
  for (auto _ : state) benchmark::DoNotOptimize(readVectorMap(log.mapFiles().vectorMap).laneSegments.size());
}
BENCHMARK(BM_ReadVectorMap)->Unit(benchmark::kMillisecond);

void BM_ReadGroundHeightNpy(benchmark::State& state) {
  const ArgoverseLog log(kLog);
  for (auto _ : state) benchmark::DoNotOptimize(readNpy(log.mapFiles().groundHeight).values.size());
}
BENCHMARK(BM_ReadGroundHeightNpy)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hdprior
