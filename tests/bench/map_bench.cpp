// HD-map layer speed: rasterising the real map at 0.10 m plus building the 1 m NDT grid
// (target < 150 ms), scoring 20,000 points with gradient and Hessian (target < 1 ms), and
// the other layers for reference.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

#include <Eigen/Geometry>

#include "engine/io/vector_map.h"
#include "engine/map/boundary_distance.h"
#include "engine/map/drivable_raster.h"
#include "engine/map/ndt_grid.h"
#include "engine/map/ndt_score.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

const fs::path kLog = fs::path(HDPRIOR_SHARED_DATA) / "av2" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede";

const VectorMap& realMap() {
  static const VectorMap map = [] {
    for (const auto& e : fs::directory_iterator(kLog / "map")) {
      if (e.path().filename().string().starts_with("log_map_archive_")) return readVectorMap(e.path());
    }
    throw std::runtime_error("no vector map in " + kLog.string());
  }();
  return map;
}

const DrivableRaster& realRaster() {
  static const DrivableRaster raster = DrivableRaster::build(realMap(), {}, "real");
  return raster;
}

void BM_RasteriseAndBuildNdtGrid(benchmark::State& state) {
  const VectorMap& map = realMap();
  for (auto _ : state) {
    const DrivableRaster raster = DrivableRaster::build(map, {}, "real");
    const NdtGrid grid = NdtGrid::build(raster);
    benchmark::DoNotOptimize(grid.validCellCount());
  }
}
BENCHMARK(BM_RasteriseAndBuildNdtGrid)->Unit(benchmark::kMillisecond);

void BM_Rasterise(benchmark::State& state) {
  const VectorMap& map = realMap();
  for (auto _ : state) benchmark::DoNotOptimize(DrivableRaster::build(map, {}, "real").drivableCellCount());
}
BENCHMARK(BM_Rasterise)->Unit(benchmark::kMillisecond);

void BM_BuildNdtGrid(benchmark::State& state) {
  const DrivableRaster& raster = realRaster();
  const double size = double(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(NdtGrid::build(raster, {.cellSize = size}).validCellCount());
}
BENCHMARK(BM_BuildNdtGrid)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

void BM_BoundaryDistance(benchmark::State& state) {
  const DrivableRaster& raster = realRaster();
  for (auto _ : state) benchmark::DoNotOptimize(BoundaryDistance::build(raster).values().data());
}
BENCHMARK(BM_BoundaryDistance)->Unit(benchmark::kMillisecond);

// 20,000 drivable points within 40 m of a pose on the main road, in that pose's frame,
// scored at a pose 0.3 m / 0.02 rad off. Argument: the derivatives computed (NdtDerivatives).
void BM_ScoreNdt20000(benchmark::State& state) {
  const NdtGrid grid = NdtGrid::build(realRaster());
  const Eigen::Vector3d truth(5200.0, 2400.0, 0.6);
  std::vector<Eigen::Vector2d> points;
  std::mt19937_64 rng(1);
  const std::vector<Eigen::Vector2d> surface = realRaster().surfacePoints();
  std::vector<Eigen::Vector2d> near;
  for (const Eigen::Vector2d& p : surface) {
    if ((p - truth.head<2>()).norm() < 40.0) near.push_back(p);
  }
  std::shuffle(near.begin(), near.end(), rng);
  for (size_t i = 0; i < 20000 && i < near.size(); ++i) {
    points.push_back(Eigen::Rotation2D<double>(-truth.z()) * (near[i] - truth.head<2>()));
  }
  const NdtScoreParams params{.outlierRatio = 0.55};
  const NdtDerivatives derivatives = NdtDerivatives(state.range(0));
  const Eigen::Vector3d pose = truth + Eigen::Vector3d(0.3, -0.2, 0.02);
  for (auto _ : state) benchmark::DoNotOptimize(scoreNdt(grid, points, pose, params, derivatives).score);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(points.size()));
  state.SetLabel(derivatives == NdtDerivatives::GradientAndHessian ? "gradient + Hessian" : "score only");
}
BENCHMARK(BM_ScoreNdt20000)
    ->Arg(int(NdtDerivatives::GradientAndHessian))
    ->Arg(int(NdtDerivatives::None))
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace hdprior
