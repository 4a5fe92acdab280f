// The ray caster against a scene of known geometry: flat ground, a road for x < 10 with a
// curb up to the sidewalk beyond, a box, a cylinder and a moving box.
#include "engine/sim/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "engine/map/drivable_raster.h"
#include "engine/sim/scene.h"
#include "../map/synthetic_maps.h"

namespace hdprior {
namespace {

Scene flatScene() {
  const VectorMap map = test::mapOf({test::rectangle(-60, -60, 10, 60)});
  DrivableRasterOptions o;
  o.resolution = 0.1;
  const DrivableRaster raster = DrivableRaster::build(map, o, "test");
  GridGeometry g;
  g.origin = {-100, -100};
  g.resolution = 0.5;
  g.cols = g.rows = 400;
  Scene scene(g, std::vector<float>(g.cellCount(), 0.0f), BoundaryDistance::build(raster), 4.0, 1);
  scene.addBox({Eigen::Vector2d(-5, 0), 0.0, Eigen::Vector2d(1, 1), 0.0, 2.0, 50});
  scene.addCylinder({Eigen::Vector2d(0, 5), 0.5, 0.0, 3.0, 60});
  scene.index();
  return scene;
}

TEST(RayCaster, HitsTheRoadWhereAPlaneWould) {
  const Scene scene = flatScene();
  const Eigen::Vector3d dir = Eigen::Vector3d(0.3, 0.2, -1.0).normalized();
  const auto hit = castRay(scene, {}, {0, 0, 2}, dir, 200.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range, 2.0 / -dir.z(), 1e-3);
  EXPECT_EQ(hit->label, PointLabel::Road);
}

TEST(RayCaster, GrazingRayFindsTheFarGround) {
  const Scene scene = flatScene();
  const Eigen::Vector3d dir = Eigen::Vector3d(0.0, -1.0, -0.04).normalized();  // about -2.3 degrees
  const auto hit = castRay(scene, {}, {0, 0, 1.9}, dir, 200.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range, 1.9 / -dir.z(), 1e-2);
  EXPECT_EQ(hit->label, PointLabel::Road);
}

TEST(RayCaster, StopsAtTheCurbFaceAndLandsOnTheSidewalk) {
  const Scene scene = flatScene();
  // Level ray 5 cm above the road: the curb (>= 0.10 m) stops it at x = 10.
  const auto face = castRay(scene, {}, {0, -10, 0.05}, {1, 0, 0}, 200.0);
  ASSERT_TRUE(face);
  EXPECT_NEAR(face->range, 10.0, 0.1);
  EXPECT_EQ(face->label, PointLabel::SidewalkCurb);
  // Steeply down onto the sidewalk at x = 12: the hit is at curb height.
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 0, -1).normalized();
  const auto top = castRay(scene, {}, {10.0, -10, 2.0}, dir, 200.0);
  ASSERT_TRUE(top);
  const double z = 2.0 + top->range * dir.z();
  EXPECT_NEAR(z, scene.curbHeight({12.0 - z, -10}), 2e-3);
  EXPECT_GE(z, 0.10 - 1e-3);
  EXPECT_LE(z, 0.20 + 1e-3);
  EXPECT_EQ(top->label, PointLabel::SidewalkCurb);
  // Far beyond the sidewalk: other ground.
  const auto far = castRay(scene, {}, {20.0, -10, 2.0}, dir, 200.0);
  ASSERT_TRUE(far);
  EXPECT_EQ(far->label, PointLabel::OtherGround);
}

TEST(RayCaster, HitsBoxesCylindersAndMovingBoxesFirst) {
  const Scene scene = flatScene();
  const auto box = castRay(scene, {}, {0, 0, 1}, {-1, 0, 0}, 200.0);
  ASSERT_TRUE(box);
  EXPECT_NEAR(box->range, 4.0, 1e-9);
  EXPECT_EQ(box->label, PointLabel::Object);
  const auto cyl = castRay(scene, {}, {0, 0, 1}, {0, 1, 0}, 200.0);
  ASSERT_TRUE(cyl);
  EXPECT_NEAR(cyl->range, 4.5, 1e-9);
  // A ray over the cylinder's top misses it.
  EXPECT_FALSE(castRay(scene, {}, {0, 0, 3.5}, {0, 1, 0}, 200.0));
  const SceneBox car{Eigen::Vector2d(0, -3), 0.3, Eigen::Vector2d(2.3, 0.95), 0.2, 1.7, 70};
  const auto moving = castRay(scene, std::span<const SceneBox>(&car, 1), {0, 0, 1}, {0, -1, 0}, 200.0);
  ASSERT_TRUE(moving);
  EXPECT_LT(moving->range, 3.0);
  EXPECT_GT(moving->range, 0.5);
}

// Moving boxes are tested by brute force behind a cheap footprint-circle test, static ones through
// the object grid without it: the same boxes either way give the same hits, ray for ray.
TEST(RayCaster, MovingBoxesHitAsTheSameStaticBoxesDo) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<SceneBox> cars;
  for (int i = 0; i < 40; ++i) {
    cars.push_back({Eigen::Vector2d(30 * u(rng), 30 * u(rng)), 3.2 * u(rng), Eigen::Vector2d(2.3, 0.95), 0.2, 1.7, 70});
  }
  const VectorMap map = test::mapOf({test::rectangle(-60, -60, 10, 60)});
  const DrivableRaster raster = DrivableRaster::build(map, {.resolution = 0.1}, "test");
  GridGeometry g;
  g.origin = {-100, -100};
  g.resolution = 0.5;
  g.cols = g.rows = 400;
  Scene empty(g, std::vector<float>(g.cellCount(), 0.0f), BoundaryDistance::build(raster), 4.0, 1);
  Scene parked = empty;
  for (const SceneBox& car : cars) parked.addBox(car);
  empty.index();
  parked.index();
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d origin(35 * u(rng), 35 * u(rng), 1 + u(rng));
    const Eigen::Vector3d dir = Eigen::Vector3d(u(rng), u(rng), 0.3 * u(rng)).normalized();
    const auto moving = castRayObjects(empty, cars, origin, dir, 200.0);
    const auto still = castRayObjects(parked, {}, origin, dir, 200.0);
    ASSERT_EQ(moving.has_value(), still.has_value()) << "ray " << i;
    if (!moving) continue;
    ++hits;
    EXPECT_EQ(moving->range, still->range) << "ray " << i;
    EXPECT_EQ(moving->cosIncidence, still->cosIncidence) << "ray " << i;
  }
  EXPECT_GT(hits, 2000);  // 3,143 of the 20,000 rays hit a car
}

TEST(RayCaster, RaysIntoTheSkyReturnNothing) {
  const Scene scene = flatScene();
  EXPECT_FALSE(castRay(scene, {}, {0, -20, 2}, Eigen::Vector3d(0, -1, 0.1).normalized(), 200.0));
  EXPECT_FALSE(castRay(scene, {}, {0, -20, 2}, Eigen::Vector3d(0, -1, -0.001).normalized(), 200.0));  // beyond range
}

}  // namespace
}  // namespace hdprior
