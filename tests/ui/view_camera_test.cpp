#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "render/scene.h"
#include "render/snapshot.h"
#include "test_data.h"
#include "ui/view_camera.h"

namespace hdprior::test {
namespace {

TEST(ViewCamera, TopDownCentrePixelPicksTheTargetOnAFlatGround) {
  ui::ViewCamera camera;
  camera.topDown = true;
  camera.target = {12.0, -7.0, 3.0};
  const render::Scene scene;  // no map: the ground is the plane z = fallback
  const auto hit = ui::pickGround(camera.camera(1.0), {99.5, 99.5}, 200, 200, scene, 1.5);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->x(), 12.0, 1e-3);
  EXPECT_NEAR(hit->y(), -7.0, 1e-3);
  EXPECT_DOUBLE_EQ(hit->z(), 1.5);
  // North up: a pixel above the centre is north of the target.
  const auto north = ui::pickGround(camera.camera(1.0), {99.5, 10.0}, 200, 200, scene, 1.5);
  ASSERT_TRUE(north);
  EXPECT_GT(north->y(), -7.0 + 30.0);
  EXPECT_NEAR(north->x(), 12.0, 1e-3);
}

TEST(ViewCamera, OrbitRaysAboveTheHorizonMissTheGround) {
  ui::ViewCamera camera;
  camera.pitch = 0.2;
  const render::Scene scene;
  EXPECT_TRUE(ui::pickGround(camera.camera(1.6), {640, 700}, 1280, 800, scene, 0.0));
  EXPECT_FALSE(ui::pickGround(camera.camera(1.6), {640, 2}, 1280, 800, scene, 0.0));
}

TEST(ViewCamera, TopDownPanMovesOneViewHeightPerViewportHeight) {
  ui::ViewCamera camera;
  camera.topDown = true;
  camera.topHeight = 80.0;
  camera.pan(-400.0, 0.0, 800.0);  // drag left by half the viewport height
  EXPECT_NEAR(camera.target.x(), 40.0, 1e-9);
  EXPECT_FALSE(camera.followEgo);
  camera.zoom(1.0);
  EXPECT_LT(camera.topHeight, 80.0);
}

// On the real map, the orbit view's centre ray lands on the ground-height surface under the ego.
TEST(ViewCamera, PicksTheGroundHeightSurfaceOfTheRealMap) {
  const ArgoverseLog log(sharedLog());
  const HdMap map = HdMap::load(log.mapFiles(), render::renderMapOptions());
  const render::Scene scene = render::makeScene(log, map);
  const render::Frame frame = render::makeFrame(scene, 0);
  ui::ViewCamera camera;
  camera.target = frame.cityTEgo.translation() - scene.origin + Eigen::Vector3d(0, 0, frame.groundZ - frame.cityTEgo.translation().z());
  const auto hit = ui::pickGround(camera.camera(1.6), {639.5, 399.5}, 1280, 800, scene, 0.0);
  ASSERT_TRUE(hit);
  const Eigen::Vector3d city = *hit + scene.origin;
  const double ground = map.groundHeight().bilinearAt(city.head<2>());
  ASSERT_TRUE(std::isfinite(ground));
  EXPECT_NEAR(city.z(), ground, 0.01);
  EXPECT_NEAR((city.head<2>() - frame.cityTEgo.translation().head<2>()).norm(), 0.0, 0.5);
}

}  // namespace
}  // namespace hdprior::test
