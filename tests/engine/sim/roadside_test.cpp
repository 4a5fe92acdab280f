// The physical roadside of scene families against a straight kerb at x = 10 (road for x < 10):
// kerb shapes, gutter and camber, a kerb of height 0 without a step, the map error field
// bounded and smooth and the kerb moved by it, raised islands the map paints over.
#include "engine/sim/roadside.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/map/drivable_raster.h"
#include "engine/sim/ray_caster.h"
#include "engine/sim/scene.h"
#include "../map/synthetic_maps.h"

namespace hdprior {
namespace {

// Every varying and sloped part switched off: a vertical kerb of `kerb` metres, flat elsewhere.
RoadsideOptions plain(double kerb) {
  RoadsideOptions o;
  o.kerbHeightMin = o.kerbHeightMax = kerb;
  o.sidewalkWidthMin = o.sidewalkWidthMax = 4.0;
  return o;
}

Scene straightKerbScene(const RoadsideOptions& o, std::vector<TrafficIsland> islands = {}) {
  const VectorMap map = test::mapOf({test::rectangle(-60, -60, 10, 60)});
  const DrivableRaster raster = DrivableRaster::build(map, {}, "test");
  GridGeometry g;
  g.origin = {-100, -100};
  g.resolution = 0.5;
  g.cols = g.rows = 400;
  Scene scene(g, std::vector<float>(g.cellCount(), 0.0f), BoundaryDistance::build(raster), 4.0, 1);
  scene.setRoadside(Roadside::build(o, {-70, -70}, {70, 70}, raster.boundaryPoints(), islands, 3));
  scene.index();
  return scene;
}

TEST(Roadside, KerbOfHeightZeroGivesNoStep) {
  const Scene scene = straightKerbScene(plain(0.0));
  for (double x = 8.0; x <= 12.0; x += 0.01) EXPECT_NEAR(scene.surfaceHeight({x, 3.0}), 0.0, 1e-9) << x;
  // A level ray 5 cm above the road crosses the kerb line without a return.
  EXPECT_FALSE(castRay(scene, {}, {0, -10, 0.05}, {1, 0, 0}, 40.0));
  // With a kerb it stops at the face.
  const Scene kerbed = straightKerbScene(plain(0.15));
  const auto face = castRay(kerbed, {}, {0, -10, 0.05}, {1, 0, 0}, 40.0);
  ASSERT_TRUE(face);
  EXPECT_NEAR(face->range, 10.0, 0.05);
  EXPECT_EQ(face->label, PointLabel::SidewalkCurb);
}

TEST(Roadside, ProfileHasGutterCamberMountableKerbAndSidewalkSlope) {
  RoadsideOptions o = plain(0.15);
  o.gutterWidth = 0.4;
  o.gutterDepth = 0.04;
  o.camber = 0.02;
  o.camberCap = 3.0;
  o.sidewalkSlope = 0.03;
  const Roadside r = Roadside::build(o, {-10, -10}, {10, 10}, {}, {}, 1);
  Roadside::Sample s = r.at({0, 0});
  EXPECT_NEAR(r.rise(-1e-6, s), -0.04, 1e-4);           // deepest at the kerb
  EXPECT_NEAR(r.rise(-0.2, s), 0.02 * 0.2 - 0.02, 1e-9);  // half way up the gutter
  EXPECT_NEAR(r.rise(-2.0, s), 0.04, 1e-9);              // camber
  EXPECT_NEAR(r.rise(-8.0, s), 0.06, 1e-9);              // capped
  EXPECT_NEAR(r.rise(0.0, s), 0.15, 1e-6);               // vertical kerb
  EXPECT_NEAR(r.rise(2.0, s), 0.15 + 0.06, 1e-6);        // sidewalk cross slope
  EXPECT_NEAR(r.rise(10.0, s), 0.15 + 0.12, 1e-6);       // flat verge beyond (no relief)
  s.kerbSlopeWidth = 0.5f;                               // mountable: the step spread over 0.5 m
  EXPECT_NEAR(r.rise(0.25, s), 0.075 + 0.03 * 0.25, 1e-6);
  EXPECT_NEAR(r.rise(0.0, s), 0.0, 1e-9);
  EXPECT_LE(r.maxRise(), 0.15 + 0.12 + 1e-9);
  EXPECT_GE(r.maxRise(), 0.15 + 0.12 - 1e-9);
}

TEST(Roadside, MapErrorFieldIsBoundedByItsAmplitudeAndSmooth) {
  RoadsideOptions o = plain(0.15);
  o.mapErrorAmplitude = 0.25;
  o.mapErrorWavelength = 40.0;
  const Roadside r = Roadside::build(o, {-150, -150}, {150, 150}, {}, {}, 9);
  double largest = 0.0, steepest = 0.0, gridError = 0.0;
  for (double y = -150; y <= 150; y += 0.7)
    for (double x = -150; x <= 150; x += 0.7) {
      const double f = r.mapErrorField({x, y});
      largest = std::max(largest, std::abs(f));
      const double fx = r.mapErrorField({x + 0.01, y}), fy = r.mapErrorField({x, y + 0.01});
      steepest = std::max(steepest, std::hypot(fx - f, fy - f) / 0.01);
      if (std::max(std::abs(x), std::abs(y)) < 149.0)  // the grid is clamped at its border
        gridError = std::max(gridError, std::abs(double(r.at({x, y}).mapOffset) - f));
    }
  EXPECT_LE(largest, 0.25 + 1e-9);
  EXPECT_GT(largest, 0.12);  // the field reaches a good part of its amplitude
  // Wavelengths of at least 0.8 x 40 m: slope at most 2 pi A / 32 m.
  EXPECT_LE(steepest, 0.25 * 2.0 * std::numbers::pi / 32.0 * 1.001);
  EXPECT_GT(steepest, 0.005);
  EXPECT_LT(gridError, 0.003);
  std::printf("[ info ] map error: largest %.3f m, steepest %.4f m/m, grid error %.4f m\n", largest, steepest, gridError);
}

TEST(Roadside, KerbLiesWhereTheMapErrorMovesIt) {
  RoadsideOptions o = plain(0.15);
  o.mapErrorAmplitude = 0.3;
  o.mapErrorWavelength = 30.0;
  const Scene scene = straightKerbScene(o);
  const Roadside& r = *scene.roadside();
  double moved = 0.0;
  for (double y = -40; y <= 40; y += 2.0) {
    const double f = r.mapErrorField({10.0, y});
    moved = std::max(moved, std::abs(f));
    EXPECT_NEAR(scene.mapBoundaryDistance({10.0, y}), 0.0, 0.01) << y;  // the map stays
    EXPECT_NEAR(scene.boundaryDistance({10.0 + f, y}), 0.0, 0.02) << y;  // the kerb moves
    const auto face = castRay(scene, {}, {0, y, 0.05}, {1, 0, 0}, 40.0);
    ASSERT_TRUE(face) << y;
    EXPECT_NEAR(face->range, 10.0 + f, 0.03) << y;
  }
  EXPECT_GT(moved, 0.1);
}

TEST(Roadside, IslandsAreRaisedInsideTheDrivableArea) {
  const TrafficIsland island{{-20, 0}, {-10, 0}, 0.8};
  EXPECT_NEAR(island.inside({-15, 0}), 0.8, 1e-12);
  EXPECT_NEAR(island.inside({-15, 0.8}), 0.0, 1e-12);
  EXPECT_NEAR(island.inside({-5, 0}), -4.2, 1e-12);
  const Scene scene = straightKerbScene(plain(0.15), {island});
  EXPECT_LT(scene.mapBoundaryDistance({-15, 0}), -20.0);  // the map paints over it
  EXPECT_GT(scene.boundaryDistance({-15, 0}), 0.5);
  EXPECT_NEAR(scene.surfaceHeight({-15, 0.5}), 0.15, 1e-3);
  EXPECT_NEAR(scene.surfaceHeight({-15, 3.0}), 0.0, 1e-6);
  // Seen from above: an island top, labelled like a sidewalk; the road around it.
  const auto top = castRay(scene, {}, {-15, 0, 2}, {0, 0, -1}, 40.0);
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->range, 2.0 - 0.15, 1e-3);
  EXPECT_EQ(top->label, PointLabel::SidewalkCurb);
  const auto road = castRay(scene, {}, {-15, 3, 2}, {0, 0, -1}, 40.0);
  ASSERT_TRUE(road);
  EXPECT_EQ(road->label, PointLabel::Road);
}

TEST(Roadside, ReflectivityPerSurface) {
  RoadsideOptions o = plain(0.15);
  o.roadReflectivity = 9;
  o.sidewalkReflectivity = 40;
  o.terrainReflectivity = 15;
  const Scene scene = straightKerbScene(o);
  const Eigen::Vector3d down(0, 0, -1);
  EXPECT_EQ(castRay(scene, {}, {5, 0, 2}, down, 40.0)->reflectivity, 9);
  EXPECT_EQ(castRay(scene, {}, {12, 0, 2}, down, 40.0)->reflectivity, 40);
  EXPECT_EQ(castRay(scene, {}, {20, 0, 2}, down, 40.0)->reflectivity, 15);
}

}  // namespace
}  // namespace hdprior
