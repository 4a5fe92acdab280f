#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/error.h"
#include "render/camera.h"
#include "render/layer_registry.h"
#include "render/snapshot.h"

namespace hdprior::test {
namespace {

Eigen::Vector3f toNdc(const render::Camera& camera, const Eigen::Vector3d& p) {
  const Eigen::Vector4f clip = camera.viewProjection() * Eigen::Vector4f(float(p.x()), float(p.y()), float(p.z()), 1);
  return clip.head<3>() / clip.w();
}

TEST(Camera, TopDownIsNorthUpAndCentred) {
  const Eigen::Vector3d centre(100, 50, 3);
  const render::Camera camera = render::topDownCamera(centre, 80.0, 16.0 / 9.0);
  EXPECT_TRUE(toNdc(camera, centre).head<2>().isZero(1e-5));
  const Eigen::Vector3f north = toNdc(camera, centre + Eigen::Vector3d(0, 20, 0));
  EXPECT_NEAR(north.x(), 0.0f, 1e-5);
  EXPECT_NEAR(north.y(), 0.5f, 1e-5);  // 20 m of a half-height of 40 m
  const Eigen::Vector3f east = toNdc(camera, centre + Eigen::Vector3d(20, 0, 0));
  EXPECT_NEAR(east.x(), 0.5f * 9.0f / 16.0f, 1e-5);
  EXPECT_NEAR(east.y(), 0.0f, 1e-5);
}

TEST(Camera, OrbitLooksAtTargetFromBehind) {
  const Eigen::Vector3d target(10, -5, 2);
  const double yaw = std::numbers::pi / 2;  // looking north
  const render::Camera camera = render::orbitCamera(target, yaw, 0.5, 40.0, 1.5);
  const Eigen::Vector3f t = toNdc(camera, target);
  EXPECT_TRUE(t.head<2>().isZero(1e-5));
  EXPECT_GT(t.z(), -1.0f);
  EXPECT_LT(t.z(), 1.0f);
  // A point further north along the ground lies above the target on screen.
  EXPECT_GT(toNdc(camera, target + Eigen::Vector3d(0, 10, 0)).y(), 0.0f);
  // East is to the right when looking north.
  EXPECT_GT(toNdc(camera, target + Eigen::Vector3d(3, 0, 0)).x(), 0.0f);
}

TEST(SnapshotOptions, ParsesSizesViewsAndLayers) {
  int w = 0, h = 0;
  render::parseSize("640x360", w, h);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 360);
  for (const char* bad : {"640", "640x", "x360", "640x360x", "10x10", "640x99999", "-640x360", "640X360"})
    EXPECT_THROW(render::parseSize(bad, w, h), Error) << bad;
  EXPECT_EQ(render::parseView("orbit"), render::View::Orbit);
  EXPECT_EQ(render::parseView("landscape"), render::View::Landscape);
  EXPECT_EQ(render::parseView("inspector"), render::View::Inspector);
  EXPECT_THROW(render::parseView("Top"), Error);
  EXPECT_EQ(render::defaultLayers(render::View::Landscape),
            (std::vector<std::string>{"drivable", "landscape", "boundary", "road_points", "match"}));
  // The analysis layers need the pipeline; the map's layers (and the NDT cells) do not.
  for (const char* name : {"landscape", "odometry_trajectory", "optimized_trajectory", "file_trajectory", "keyframes", "road_points", "match"})
    EXPECT_TRUE(render::needsAnalysis(name)) << name;
  for (const char* name : {"ground", "ndt_cells", "trajectory", "sweep"}) EXPECT_FALSE(render::needsAnalysis(name)) << name;
  // Drawing order, not the order given.
  EXPECT_EQ(render::parseLayerList("ego,sweep,ground"), (std::vector<std::string>{"ground", "sweep", "ego"}));
  // "all" is the standard layers; the extras are drawn when named.
  EXPECT_EQ(render::parseLayerList("all"),
            (std::vector<std::string>{"ground", "drivable", "boundary", "lanes", "trajectory", "sweep", "ego"}));
  EXPECT_EQ(render::parseLayerList("accumulated,crossings"), (std::vector<std::string>{"crossings", "accumulated"}));
  EXPECT_THROW(render::parseLayerList("sweep,"), Error);
  EXPECT_THROW(render::parseLayerList("clouds"), Error);
  for (const auto& name : render::layerNames()) EXPECT_EQ(render::makeLayer(name)->name(), name);
}

}  // namespace
}  // namespace hdprior::test
