// The signed distance to the drivable boundary: known values on a square, exactness of the
// transform against brute force, and sign agreement with the raster on the real map.
#include "engine/map/boundary_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/io/vector_map.h"
#include "engine/map/drivable_raster.h"
#include "synthetic_maps.h"
#include "test_data.h"

namespace hdprior {
namespace {

using test::mapOf;
using test::rectangle;
using test::ring;

TEST(BoundaryDistance, SquareHasKnownDistances) {
  const DrivableRaster raster = DrivableRaster::build(mapOf({rectangle(0, 0, 10, 10)}), {.margin = 10.0}, "square");
  const BoundaryDistance sdf = BoundaryDistance::build(raster);
  const double cell = 0.1;
  EXPECT_NEAR(sdf.distance({5.0, 5.0}), -5.0, cell);
  EXPECT_NEAR(sdf.distance({1.0, 5.0}), -1.0, cell);
  EXPECT_NEAR(sdf.distance({13.0, 5.0}), 3.0, cell);
  EXPECT_NEAR(sdf.distance({5.0, -2.0}), 2.0, cell);
  EXPECT_NEAR(sdf.distance({13.0, 14.0}), 5.0, cell);  // nearest boundary point is the corner (10, 10)
  EXPECT_NEAR(sdf.distance({10.0, 5.0}), 0.0, cell);
  EXPECT_NEAR(sdf.distance({0.0, 0.0}), 0.0, cell);
  EXPECT_TRUE(std::isnan(sdf.distance({100.0, 5.0})));
  // Cell values: the centre (5.05, 5.05) is 50 cells from the nearest empty cell centre
  // (10.05, 5.05): 50 * 0.1 - 0.05 = 4.95 m inside, its exact distance to the edge x = 10.
  int col, row;
  ASSERT_TRUE(sdf.geometry().cellOf({5.05, 5.05}, col, row));
  EXPECT_NEAR(sdf.at(col, row), -4.95, 1e-5);
}

// Brute force over all cell pairs on a small raster of an irregular shape.
TEST(BoundaryDistance, IsTheExactEuclideanTransform) {
  const VectorMap map = mapOf({ring({{0, 0}, {7, 1}, {6, 6}, {3, 3.5}, {1, 7}}), rectangle(8, 0, 9, 9)});
  const DrivableRaster raster = DrivableRaster::build(map, {.resolution = 0.25, .margin = 1.0}, "shape");
  const BoundaryDistance sdf = BoundaryDistance::build(raster);
  const GridGeometry& g = raster.geometry();
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.cols; ++c) {
      const bool inside = raster.drivable(c, r);
      double best = std::numeric_limits<double>::infinity();
      for (int r2 = 0; r2 < g.rows; ++r2) {
        for (int c2 = 0; c2 < g.cols; ++c2) {
          if (raster.drivable(c2, r2) != inside) best = std::min(best, std::hypot(double(c2 - c), double(r2 - r)));
        }
      }
      const double expected = (best - 0.5) * g.resolution * (inside ? -1.0 : 1.0);
      ASSERT_NEAR(sdf.at(c, r), expected, 1e-5) << "cell " << c << ", " << r;
    }
  }
}

TEST(BoundaryDistance, RealMapSignMatchesTheRaster) {
  std::filesystem::path vectorMap;
  for (const auto& e : std::filesystem::directory_iterator(test::sharedLog() / "map")) {
    if (e.path().filename().string().starts_with("log_map_archive_")) vectorMap = e.path();
  }
  const DrivableRaster raster = DrivableRaster::build(readVectorMap(vectorMap), {}, "real");
  const BoundaryDistance sdf = BoundaryDistance::build(raster);
  const GridGeometry& g = raster.geometry();
  size_t wrongSign = 0;
  float deepest = 0.0f;
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.cols; ++c) {
      const float d = sdf.at(c, r);
      wrongSign += raster.drivable(c, r) ? !(d < 0) : !(d > 0);
      deepest = std::min(deepest, d);
    }
  }
  EXPECT_EQ(wrongSign, 0u);
  EXPECT_LT(deepest, -5.0f);   // the main road is wider than 10 m
  EXPECT_GT(deepest, -30.0f);  // and narrower than 60 m
  // Curb points lie on the zero level to within a cell.
  for (size_t i = 0; i < raster.boundaryPoints().size(); i += 97) {
    EXPECT_LT(std::abs(sdf.distance(raster.boundaryPoints()[i])), 0.15) << raster.boundaryPoints()[i].transpose();
  }
}

}  // namespace
}  // namespace hdprior
