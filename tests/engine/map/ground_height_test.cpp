// Ground height: Argoverse query semantics, NaN-aware bilinear interpolation and its
// gradient, roll/pitch, the real raster against the real poses, and the GeoTIFF round trip.
#include "engine/map/ground_height.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/geotiff.h"
#include "test_data.h"

namespace hdprior {
namespace {

// The height of the ego-vehicle origin above the ground-height raster, measured on this log
// as the mean of z - heightAt(x, y) over all 2706 poses: 0.3196 m (standard deviation
// 0.028 m; the data README gives about 0.32 m over four logs).
constexpr double kEgoOriginAboveGround = 0.3196;

// A plane z = 5 + 0.1 x - 0.2 y sampled at pixel centres, with a rotated, scaled Sim2.
GroundHeight planeRaster(std::vector<std::pair<int, int>> nanPixels = {}) {
  Sim2 sim2;
  sim2.R = Eigen::Rotation2Dd(0.3).toRotationMatrix();
  sim2.t = Eigen::Vector2d(4.0, -2.0);
  sim2.s = 2.5;
  const int rows = 30, cols = 40;
  std::vector<float> heights(size_t(rows * cols));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector2d p = sim2.imageToCity(Eigen::Vector2d(c + 0.5, r + 0.5));
      heights[size_t(r * cols + c)] = float(5.0 + 0.1 * p.x() - 0.2 * p.y());
    }
  }
  for (const auto& [c, r] : nanPixels) heights[size_t(r * cols + c)] = NAN;
  return GroundHeight(sim2, rows, cols, std::move(heights), "plane");
}

TEST(GroundHeight, QueryUsesFloorOfImageCoordinates) {
  const GroundHeight h = planeRaster();
  const Sim2& sim2 = h.imgSim2City();
  for (const Eigen::Vector2d& uv : {Eigen::Vector2d(3.2, 7.9), Eigen::Vector2d(0.01, 0.01), Eigen::Vector2d(39.99, 29.5)}) {
    const Eigen::Vector2d p = sim2.imageToCity(uv);
    EXPECT_EQ(h.heightAt(p), h.pixel(int(std::floor(uv.x())), int(std::floor(uv.y())))) << uv.transpose();
  }
  EXPECT_TRUE(std::isnan(h.heightAt(sim2.imageToCity({-0.01, 5.0}))));
  EXPECT_TRUE(std::isnan(h.heightAt(sim2.imageToCity({40.001, 5.0}))));
  EXPECT_TRUE(std::isnan(h.heightAt(sim2.imageToCity({5.0, 30.001}))));
  EXPECT_TRUE(std::isnan(h.heightAt({NAN, 0.0})));
}

TEST(GroundHeight, BilinearAndGradientAreExactOnAPlane) {
  const GroundHeight h = planeRaster();
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.5, 39.5), v(0.5, 29.5);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector2d p = h.imgSim2City().imageToCity({u(rng), v(rng)});
    EXPECT_NEAR(h.bilinearAt(p), 5.0 + 0.1 * p.x() - 0.2 * p.y(), 1e-5);
    EXPECT_LT((h.gradientAt(p) - Eigen::Vector2d(0.1, -0.2)).norm(), 1e-5);
    if (h.imgSim2City().cityToImage(p).minCoeff() > 3.0 && (h.imgSim2City().cityToImage(p) - Eigen::Vector2d(40, 30)).maxCoeff() < -3.0) {
      EXPECT_LT((h.slopeAt(p, 1.0) - Eigen::Vector2d(0.1, -0.2)).norm(), 1e-5);
    }
  }
  EXPECT_TRUE(std::isnan(h.slopeAt(h.imgSim2City().imageToCity({-5, -5}), 1.0).x()));
  EXPECT_TRUE(std::isnan(h.slopeAt(h.imgSim2City().imageToCity({5, 5}), 0.1).x()));  // too few pixels
}

TEST(GroundHeight, NanAwareInterpolationKeepsTheRegionOfInterest) {
  const GroundHeight h = planeRaster({{10, 10}, {11, 10}, {20, 5}});
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 41.0), v(-1.0, 31.0);
  const double step = 1e-6;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector2d p = h.imgSim2City().imageToCity({u(rng), v(rng)});
    const double b = h.bilinearAt(p);
    ASSERT_EQ(std::isnan(b), std::isnan(h.heightAt(p))) << p.transpose();
    if (std::isnan(b)) continue;
    // Where neighbours are missing the surface is still close to the plane and smooth.
    EXPECT_NEAR(b, 5.0 + 0.1 * p.x() - 0.2 * p.y(), 0.15);
    const Eigen::Vector2d g = h.gradientAt(p);
    Eigen::Vector2d fd;
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector2d e = Eigen::Vector2d::Unit(k) * step;
      const double plus = h.bilinearAt(p + e), minus = h.bilinearAt(p - e);
      if (std::isnan(plus) || std::isnan(minus)) fd(k) = g(k);  // at the region's edge
      else fd(k) = (plus - minus) / (2 * step);
    }
    EXPECT_LT((g - fd).norm(), 1e-4) << p.transpose();
  }
}

TEST(GroundHeight, RollPitchAlignTheVehicleWithTheSurfaceNormal) {
  for (const Eigen::Vector2d& g : {Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(-0.05, 0.3), Eigen::Vector2d(0, 0)}) {
    const Eigen::Vector3d normal = Eigen::Vector3d(-g.x(), -g.y(), 1.0).normalized();
    for (double yaw : {0.0, 0.7, -2.5}) {
      const RollPitch rp = rollPitchFromGradient(g, yaw);
      const Eigen::Matrix3d R = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(rp.pitch, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(rp.roll, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
      EXPECT_LT((R.col(2) - normal).norm(), 1e-12) << g.transpose() << " yaw " << yaw;
    }
  }
  // Driving uphill (+x rises) pitches the nose up, i.e. a negative rotation about y.
  EXPECT_LT(rollPitchFromGradient({0.1, 0.0}, 0.0).pitch, 0.0);
}

TEST(GroundHeight, BadRastersThrow) {
  EXPECT_THROW(GroundHeight(Sim2{}, 2, 3, std::vector<float>(5), "x"), Error);
  EXPECT_THROW(GroundHeight(Sim2{}, 0, 3, {}, "x"), Error);
  Sim2 bad;
  bad.s = 0.0;
  EXPECT_THROW(GroundHeight(bad, 1, 1, std::vector<float>(1), "x"), Error);
  NpyArray oneD;
  oneD.shape = {4};
  oneD.values.resize(4);
  EXPECT_THROW(GroundHeight::fromNpy(oneD, Sim2{}, "x.npy"), Error);
  EXPECT_THROW(readGroundHeightGeoTiff("/nonexistent/height.tif"), Error);
}

TEST(GroundHeight, RealRasterAgreesWithThePoses) {
  const ArgoverseLog log(test::sharedLog());
  const GroundHeight h = readGroundHeight(log.mapFiles().groundHeight, log.mapFiles().sim2);
  EXPECT_EQ(h.rows(), 785);
  EXPECT_EQ(h.cols(), 880);
  // A pixel centre answers its own pixel: image (400.5, 350.5) is city (5192.55, 2389.05).
  const Eigen::Vector2d city = h.imgSim2City().imageToCity({400.5, 350.5});
  EXPECT_NEAR(city.x(), 5072.400390625 + 400.5 * 0.3, 1e-9);
  EXPECT_NEAR(city.y(), 2283.900390625 + 350.5 * 0.3, 1e-9);
  ASSERT_FALSE(std::isnan(h.pixel(400, 350)));
  EXPECT_EQ(h.heightAt(city), h.pixel(400, 350));
  const std::vector<SE3>& poses = log.cityTEgo().poses();
  double rollError = 0.0, pitchError = 0.0;
  for (size_t k = 0; k < 10; ++k) {
    const Eigen::Vector3d t = poses[k * (poses.size() - 1) / 9].translation();
    const double ground = h.heightAt(t.head<2>());
    ASSERT_FALSE(std::isnan(ground)) << t.transpose();
    EXPECT_NEAR(ground, t.z() - kEgoOriginAboveGround, 0.10) << "pose " << k * (poses.size() - 1) / 9;
    EXPECT_NEAR(h.bilinearAt(t.head<2>()), t.z() - kEgoOriginAboveGround, 0.10);
    // Per-pixel gradients carry the float16 quantisation (1/16 m over 0.3 m) ...
    EXPECT_LT(h.gradientAt(t.head<2>()).norm(), 0.35);
    // ... the plane under the vehicle does not, and gives the pose's roll and pitch.
    const Eigen::Matrix3d R = poses[k * (poses.size() - 1) / 9].rotation();
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    const double pitch = -std::asin(std::clamp(R(2, 0), -1.0, 1.0)), roll = std::atan2(R(2, 1), R(2, 2));
    const RollPitch surface = h.rollPitchAt(t.head<2>(), yaw);
    // Measured: at most 1.3 degrees apart (suspension, and the map's smoothing), 0.35 / 0.63 degrees on average.
    EXPECT_NEAR(surface.roll, roll, 1.5 * M_PI / 180) << "pose " << k;
    EXPECT_NEAR(surface.pitch, pitch, 1.5 * M_PI / 180) << "pose " << k;
    rollError += std::abs(surface.roll - roll) / 10;
    pitchError += std::abs(surface.pitch - pitch) / 10;
  }
  EXPECT_LT(rollError, 0.8 * M_PI / 180);
  EXPECT_LT(pitchError, 0.8 * M_PI / 180);
}

TEST(GroundHeight, GeoTiffRoundTripAnswersLikeTheNpy) {
  const ArgoverseLog log(test::sharedLog());
  const GroundHeight npy = readGroundHeight(log.mapFiles().groundHeight, log.mapFiles().sim2);
  const auto dir = test::freshOutputDir("ground_height_geotiff");
  writeGroundHeightGeoTiff(dir / "ground_height.tif", npy);
  const GroundHeight tif = readGroundHeightGeoTiff(dir / "ground_height.tif");
  ASSERT_EQ(tif.rows(), npy.rows());
  ASSERT_EQ(tif.cols(), npy.cols());
  EXPECT_LT((tif.imgSim2City().R - npy.imgSim2City().R).norm(), 1e-12);
  EXPECT_LT((tif.imgSim2City().t - npy.imgSim2City().t).norm(), 1e-9);
  EXPECT_NEAR(tif.imgSim2City().s, npy.imgSim2City().s, 1e-12);
  size_t nan = 0;
  for (size_t i = 0; i < npy.heights().size(); ++i) {
    const float a = npy.heights()[i], b = tif.heights()[i];
    ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i;
    nan += std::isnan(a);
  }
  EXPECT_GT(nan, 1000u);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(5060, 5350), y(2270, 2530);
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector2d p(x(rng), y(rng));
    const double a = npy.heightAt(p), b = tif.heightAt(p);
    ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << p.transpose();
    const double ba = npy.bilinearAt(p), bb = tif.bilinearAt(p);
    ASSERT_TRUE(std::abs(ba - bb) < 1e-9 || (std::isnan(ba) && std::isnan(bb))) << p.transpose();
  }
  // What gdal sees: north-up, 0.3 m pixels, the top-left corner at the image's row 785 edge.
  const GeoRaster<float> raw = readGeoTiffFloat(dir / "ground_height.tif");
  EXPECT_NEAR(raw.transform[0], 5072.400390625, 1e-9);
  EXPECT_NEAR(raw.transform[3], 2283.900390625 + 785 * 0.3, 1e-9);
  EXPECT_NEAR(raw.transform[1], 0.3, 1e-12);
  EXPECT_NEAR(raw.transform[5], -0.3, 1e-12);
  ASSERT_TRUE(raw.noData.has_value());
  EXPECT_TRUE(std::isnan(*raw.noData));
  EXPECT_EQ(raw.values[0], npy.pixel(0, 784));  // file row 0 is the northern-most image row
}

TEST(GroundHeight, SouthUpAndNoDataValuesAreReadToo) {
  const GroundHeight plane = planeRaster({{3, 4}});
  const auto dir = test::freshOutputDir("ground_height_south_up");
  GeoRaster<float> r;
  r.rows = plane.rows();
  r.cols = plane.cols();
  // South-up: file rows in image order, transform straight from the Sim2.
  const Sim2& sim2 = plane.imgSim2City();
  const Eigen::Matrix2d image = sim2.R.transpose() / sim2.s;
  const Eigen::Vector2d origin = sim2.imageToCity({0, 0});
  r.transform = {origin.x(), image(0, 0), image(0, 1), origin.y(), image(1, 0), image(1, 1)};
  r.values = plane.heights();
  for (float& v : r.values) v = std::isnan(v) ? -9999.0f : v;
  r.noData = -9999.0;
  writeGeoTiff(dir / "south_up.tif", r);
  const GroundHeight back = readGroundHeightGeoTiff(dir / "south_up.tif");
  EXPECT_TRUE(std::isnan(back.pixel(3, 4)));
  EXPECT_LT((back.imgSim2City().R - sim2.R).norm(), 1e-12);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 40.0), v(0.0, 30.0);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector2d p = sim2.imageToCity({u(rng), v(rng)});
    const double a = plane.bilinearAt(p), b = back.bilinearAt(p);
    ASSERT_TRUE(std::abs(a - b) < 1e-9 || (std::isnan(a) && std::isnan(b)));
  }
}

}  // namespace
}  // namespace hdprior
