// The NDT grid of the drivable area: exact moments on synthetic strips, eigenvalue
// regularisation, lookup, and agreement with a brute-force computation on the real map.
#include "engine/map/ndt_grid.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "engine/error.h"
#include "engine/io/vector_map.h"
#include "engine/map/drivable_raster.h"
#include "synthetic_maps.h"
#include "test_data.h"

namespace hdprior {
namespace {

using test::mapOf;
using test::rectangle;
using test::ring;

DrivableRaster rasterOf(const VectorMap& map) { return DrivableRaster::build(map, {.margin = 2.0}, "synthetic"); }

TEST(NdtGrid, AxisAlignedStripHasTheExactSecondMomentsOfItsArea) {
  // A 0.5 m wide strip along x: each 1 m cell holds a 1 x 0.5 m rectangle, whose covariance
  // is diag(1/12, 0.25/12) with its mean at the rectangle's centre.
  const DrivableRaster raster = rasterOf(mapOf({rectangle(0, 0, 20, 0.5)}));
  const NdtGrid grid = NdtGrid::build(raster);
  EXPECT_EQ(grid.validCellCount(), 20u);
  for (int k = 0; k < 20; ++k) {
    const NdtCell* cell = grid.cellAt({k + 0.5, 0.25});
    ASSERT_NE(cell, nullptr) << k;
    EXPECT_EQ(cell->count, 50);
    EXPECT_NEAR(cell->mean.x(), k + 0.5, 1e-9);
    EXPECT_NEAR(cell->mean.y(), 0.25, 1e-9);
    EXPECT_NEAR(cell->covariance(0, 0), 1.0 / 12, 1e-9);
    EXPECT_NEAR(cell->covariance(1, 1), 0.25 / 12, 1e-9);
    EXPECT_NEAR(cell->covariance(0, 1), 0.0, 1e-9);
    EXPECT_TRUE((cell->covariance * cell->information).isIdentity(1e-9));
  }
  EXPECT_EQ(grid.cellAt({5.5, 1.5}), nullptr);
  EXPECT_EQ(grid.cellAt({-100, 0.25}), nullptr);
  EXPECT_EQ(grid.cellAt({NAN, 0.25}), nullptr);
}

TEST(NdtGrid, DiagonalRoadStripIsElongatedAlongTheRoad) {
  // A 3 m wide road at 30 degrees; 8 m cells that the road crosses fully.
  const double angle = M_PI / 6;
  const Eigen::Vector2d along(std::cos(angle), std::sin(angle)), across(-along.y(), along.x());
  const Eigen::Vector2d a = -40 * along - 1.5 * across, b = 40 * along - 1.5 * across;
  const Eigen::Vector2d c = 40 * along + 1.5 * across, d = -40 * along + 1.5 * across;
  const DrivableRaster raster = rasterOf(mapOf({ring({{a.x(), a.y()}, {b.x(), b.y()}, {c.x(), c.y()}, {d.x(), d.y()}})}));
  const NdtGrid grid = NdtGrid::build(raster, {.cellSize = 8.0});
  size_t checked = 0;
  for (const NdtCell& cell : grid.cells()) {
    if (cell.count < 2000 || cell.mean.norm() > 30) continue;  // cells the road crosses fully
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cell.covariance);
    const Eigen::Vector2d major = eig.eigenvectors().col(1);
    EXPECT_GT(std::abs(major.dot(along)), std::cos(10 * M_PI / 180)) << cell.mean.transpose();
    EXPECT_GT(eig.eigenvalues()(1), 3.0 * eig.eigenvalues()(0));
    ++checked;
  }
  EXPECT_GE(checked, 3u);
}

TEST(NdtGrid, FilledCellIsIsotropicAndThinStripIsRegularised) {
  const NdtGrid full = NdtGrid::build(rasterOf(mapOf({rectangle(0, 0, 3, 3)})));
  const NdtCell* centre = full.cellAt({1.5, 1.5});
  ASSERT_NE(centre, nullptr);
  EXPECT_TRUE(centre->covariance.isApprox(Eigen::Matrix2d::Identity() / 12, 1e-9));

  // One raster row: the raw covariance is diag(1/12, 0.01/12); a ratio of 0.1 lifts the small eigenvalue.
  const DrivableRaster thin = rasterOf(mapOf({rectangle(0, 0, 5, 0.1)}));
  const NdtGrid rawGrid = NdtGrid::build(thin, {.minEigenRatio = 1e-3});
  const NdtGrid liftedGrid = NdtGrid::build(thin, {.minEigenRatio = 0.1});
  const NdtCell* raw = rawGrid.cellAt({2.5, 0.05});
  const NdtCell* lifted = liftedGrid.cellAt({2.5, 0.05});
  ASSERT_TRUE(raw && lifted);
  EXPECT_NEAR(raw->covariance(1, 1), 0.01 / 12, 1e-12);
  EXPECT_NEAR(lifted->covariance(1, 1), 0.1 / 12, 1e-12);
  EXPECT_NEAR(lifted->covariance(0, 0), 1.0 / 12, 1e-12);
}

TEST(NdtGrid, CellsBelowMinPointsAreNotValid) {
  // A 0.3 x 0.1 m sliver: 3 raster cells, fewer than the default minPoints of 5.
  const NdtGrid grid = NdtGrid::build(rasterOf(mapOf({rectangle(0, 0, 5, 5), rectangle(10.2, 10.2, 10.5, 10.3)})));
  EXPECT_EQ(grid.cellAt({10.35, 10.25}), nullptr);
  EXPECT_NE(grid.cellAt({2.5, 2.5}), nullptr);
}

TEST(NdtGrid, BadOptionsThrow) {
  const DrivableRaster raster = rasterOf(mapOf({rectangle(0, 0, 5, 5)}));
  EXPECT_THROW(NdtGrid::build(raster, {.cellSize = 0.25}), Error);  // not a multiple of 0.1
  EXPECT_THROW(NdtGrid::build(raster, {.cellSize = 0.2, .minPoints = 5}), Error);  // 4 cells at most
  EXPECT_THROW(NdtGrid::build(raster, {.cellSize = 1.0, .minPoints = 5, .minEigenRatio = 0.0}), Error);
  EXPECT_THROW(NdtGrid::build(raster, {.cellSize = NAN}), Error);
  EXPECT_NO_THROW(NdtGrid::build(raster, {.cellSize = 0.3}));
}

// Brute force: group the raster's surface points by NDT cell and compute mean and covariance
// directly (plus the resolution^2 / 12 of the cells' own extent).
TEST(NdtGrid, RealMapMatchesBruteForceMoments) {
  std::filesystem::path vectorMap;
  for (const auto& e : std::filesystem::directory_iterator(test::sharedLog() / "map")) {
    if (e.path().filename().string().starts_with("log_map_archive_")) vectorMap = e.path();
  }
  const DrivableRaster raster = DrivableRaster::build(readVectorMap(vectorMap), {}, "real");
  for (double size : {1.0, 2.0, 4.0}) {
    const NdtGrid grid = NdtGrid::build(raster, {.cellSize = size, .minPoints = 5, .minEigenRatio = 1e-9});
    struct Sums {
      double n = 0;
      Eigen::Vector2d s = Eigen::Vector2d::Zero();
      Eigen::Matrix2d ss = Eigen::Matrix2d::Zero();
    };
    const GridGeometry& g = grid.geometry();
    std::vector<Sums> sums(g.cellCount());
    for (const Eigen::Vector2d& p : raster.surfacePoints()) {
      int col, row;
      ASSERT_TRUE(g.cellOf(p, col, row));
      const Eigen::Vector2d local = p - g.origin - Eigen::Vector2d(col, row) * size;
      Sums& s = sums[g.index(col, row)];
      s.n += 1;
      s.s += local;
      s.ss += local * local.transpose();
    }
    size_t valid = 0;
    for (int row = 0; row < g.rows; ++row) {
      for (int col = 0; col < g.cols; ++col) {
        const Sums& s = sums[g.index(col, row)];
        const NdtCell* cell = grid.at(col, row);
        if (s.n < 5) {
          EXPECT_EQ(cell, nullptr);
          continue;
        }
        ASSERT_NE(cell, nullptr);
        ++valid;
        const Eigen::Vector2d mean = s.s / s.n;
        Eigen::Matrix2d cov = s.ss / s.n - mean * mean.transpose();
        cov.diagonal().array() += 0.01 / 12;
        EXPECT_EQ(cell->count, int(s.n));
        EXPECT_LT((cell->mean - (g.origin + Eigen::Vector2d(col, row) * size + mean)).norm(), 1e-9);
        EXPECT_LT((cell->covariance - cov).norm(), 1e-9 * size * size);
      }
    }
    EXPECT_EQ(valid, grid.validCellCount()) << size;
  }
}

}  // namespace
}  // namespace hdprior
