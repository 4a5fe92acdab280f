// The world around a drive: curbs where the map's drivable area ends, objects placed by kind
// where they belong, nothing in the way of the drive, deterministic by seed.
#include "engine/sim/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/sim/town_generator.h"
#include "engine/sim/trajectory.h"

namespace hdprior {
namespace {

struct World {
  TownMap town = generateTown(TownOptions{}, 7);
  GroundHeight ground = GroundHeight::fromNpy(town.groundHeight, town.imgSim2City, "town");
  LaneGraph lanes{town.vectorMap, {}, "town"};
  PoseTrajectory route = [this] {
    RouteOptions o;
    o.seconds = 10.0;
    return routeTrajectory(lanes, ground, o, 2);
  }();
  std::vector<Eigen::Vector2d> path() const {
    std::vector<Eigen::Vector2d> p;
    for (const SE3& T : route.poses()) p.push_back(T.translation().head<2>());
    return p;
  }
};

const World& world() {
  static const World w;
  return w;
}

double distanceToPath(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& path) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& q : path) best = std::min(best, (p - q).norm());
  return best;
}

TEST(SceneBuilder, PlacesEachKindOfObjectWhereItBelongs) {
  const World& w = world();
  const auto path = w.path();
  const Scene scene = buildScene(w.town.vectorMap, w.ground, w.lanes, path, w.route.startNs(), {}, 1, "town");
  size_t cars = 0, buildings = 0;
  for (const SceneBox& b : scene.boxes()) {
    const bool car = b.halfSize.isApprox(Eigen::Vector2d(2.3, 0.95));
    if (car) {
      ++cars;
      EXPECT_LT(scene.boundaryDistance(b.centre), -0.5);  // parked on the road, by the curb
      EXPECT_GT(scene.boundaryDistance(b.centre), -3.0);
      EXPECT_GT(distanceToPath(b.centre, path), 2.5);
    } else {
      ++buildings;
      EXPECT_GT(scene.boundaryDistance(b.centre), 3.0);  // behind the sidewalk
      EXPECT_GT(b.zMax - b.zMin, 4.0);
    }
  }
  size_t poles = 0;
  for (const SceneCylinder& c : scene.cylinders()) {
    EXPECT_GT(scene.boundaryDistance(c.centre), 0.0);  // poles and trees stand off the road
    poles += c.radius < 0.15;
  }
  EXPECT_GT(cars, 20u);
  EXPECT_GT(buildings, 20u);
  EXPECT_GT(poles, 10u);
  EXPECT_GT(scene.cylinders().size(), poles + 20u);  // trees: trunk and crown
  EXPECT_EQ(scene.movingCars().size(), 30u);
  // Curb height between 0.10 and 0.20 m; the ground is the map's ground height.
  for (const Eigen::Vector2d& p : path) {
    EXPECT_GE(scene.curbHeight(p), 0.10);
    EXPECT_LE(scene.curbHeight(p), 0.20);
    EXPECT_NEAR(scene.groundHeight(p), w.ground.bilinearAt(p), 0.01);
    EXPECT_LT(scene.boundaryDistance(p), 0.0);  // the drive is on the road
  }
  std::printf("[ info ] %zu parked cars, %zu buildings, %zu poles, %zu tree parts\n", cars, buildings, poles,
              scene.cylinders().size() - poles);
}

TEST(SceneBuilder, ParkedOptionAndSeedShapeTheWorld) {
  const World& w = world();
  const auto path = w.path();
  const auto count = [&](double parked, uint64_t seed) {
    SceneOptions o;
    o.parked = parked;
    const Scene s = buildScene(w.town.vectorMap, w.ground, w.lanes, path, w.route.startNs(), o, seed, "town");
    size_t cars = 0;
    for (const SceneBox& b : s.boxes()) cars += b.halfSize.isApprox(Eigen::Vector2d(2.3, 0.95));
    return std::pair(cars, s.boxes().size());
  };
  EXPECT_EQ(count(0.0, 1).first, 0u);
  EXPECT_GT(count(1.0, 1).first, count(0.5, 1).first);
  EXPECT_EQ(count(0.5, 1), count(0.5, 1));
  EXPECT_NE(count(0.5, 1), count(0.5, 2));
}

}  // namespace
}  // namespace hdprior
