// The lane graph: centerlines, links, reachability and route walking, synthetic and real.
#include "engine/map/lane_graph.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/io/vector_map.h"
#include "engine/map/drivable_raster.h"
#include "test_data.h"

namespace hdprior {
namespace {

LaneSegment lane(int64_t id, Eigen::Vector2d from, Eigen::Vector2d to, std::vector<int64_t> successors,
                 std::vector<int64_t> predecessors = {}) {
  const Eigen::Vector2d dir = (to - from).normalized(), left(-dir.y(), dir.x());
  LaneSegment s;
  s.id = id;
  s.laneType = "VEHICLE";
  const auto at = [](const Eigen::Vector2d& p) { return Eigen::Vector3d(p.x(), p.y(), 0.0); };
  s.leftLaneBoundary = {at(from + 1.75 * left), at(to + 1.75 * left)};
  s.rightLaneBoundary = {at(from - 1.75 * left), at(0.5 * (from + to) - 1.75 * left), at(to - 1.75 * left)};
  s.successors = std::move(successors);
  s.predecessors = std::move(predecessors);
  return s;
}

// 1 -> 2 -> 3 and 1 -> 4 -> 5 -> 3 (a longer detour), 6 isolated, 3 -> 99 (outside the map).
VectorMap junction() {
  VectorMap m;
  m.laneSegments = {lane(1, {0, 0}, {10, 0}, {2, 4}),     lane(2, {10, 0}, {30, 0}, {3}, {1}),
                    lane(3, {30, 0}, {40, 0}, {99}, {2, 5}), lane(4, {10, 0}, {20, 10}, {5}, {1}),
                    lane(5, {20, 10}, {30, 0}, {3}, {4}),  lane(6, {100, 100}, {110, 100}, {})};
  return m;
}

TEST(LaneGraph, CenterlineIsTheMeanOfResampledBoundaries) {
  const Polyline3 left = {{0, 1, 0}, {10, 1, 0}};
  const Polyline3 right = {{0, -1, 2}, {2, -1, 2}, {7, -1, 2}, {10, -1, 2}};
  const Polyline3 c = laneCenterline(left, right, 1.0);
  ASSERT_EQ(c.size(), 11u);
  for (size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(c[i].x(), double(i), 1e-12);
    EXPECT_NEAR(c[i].y(), 0.0, 1e-12);
    EXPECT_NEAR(c[i].z(), 1.0, 1e-12);
  }
  const Polyline3 r = resampleByArcLength({{0, 0, 0}, {3, 4, 0}, {3, 10, 0}}, 3);  // length 11
  EXPECT_LT((r[1] - Eigen::Vector3d(3, 4.5, 0)).norm(), 1e-12);
  EXPECT_NEAR(polylineLength(r), 11.0 - 5.0 + std::hypot(3.0, 4.5) - 0.5, 1e-9);
  EXPECT_EQ(resampleByArcLength({{1, 2, 3}}, 4).size(), 4u);
}

TEST(LaneGraph, LinksReachabilityAndShortestRoute) {
  const LaneGraph g(junction(), {}, "junction");
  ASSERT_EQ(g.lanes().size(), 6u);
  EXPECT_EQ(g.droppedLinks(), 1u);  // 3 -> 99
  const size_t l1 = *g.indexOf(1), l2 = *g.indexOf(2), l3 = *g.indexOf(3), l4 = *g.indexOf(4), l6 = *g.indexOf(6);
  EXPECT_FALSE(g.indexOf(99).has_value());
  EXPECT_NEAR(g.lanes()[l2].length, 20.0, 1e-9);
  EXPECT_EQ(g.lanes()[l1].successors, (std::vector<size_t>{l2, l4}));
  EXPECT_EQ(g.lanes()[l3].predecessors.size(), 2u);
  EXPECT_EQ(g.reachable(l1).size(), 5u);
  EXPECT_EQ(g.reachable(l3), std::vector<size_t>{l3});
  EXPECT_EQ(g.reachable(l6), std::vector<size_t>{l6});
  const auto route = g.shortestRoute(l1, l3);
  ASSERT_TRUE(route.has_value());
  EXPECT_EQ(*route, (std::vector<size_t>{l1, l2, l3}));
  EXPECT_FALSE(g.shortestRoute(l3, l1).has_value());
  EXPECT_FALSE(g.shortestRoute(l1, l6).has_value());
  EXPECT_EQ(g.shortestRoute(l2, l2), std::vector<size_t>{l2});
  const Polyline3 line = g.routeCenterline(*route);
  EXPECT_NEAR(polylineLength(line), 40.0, 1e-9);
  EXPECT_EQ(g.nearestLane({15.0, 0.5}, 2.0), l2);
  EXPECT_FALSE(g.nearestLane({60.0, 60.0}, 2.0).has_value());
}

TEST(LaneGraph, RandomRoutesFollowSuccessorsAndAreSeeded) {
  const LaneGraph g(junction(), {}, "junction");
  std::mt19937_64 a(11), b(11);
  for (int i = 0; i < 20; ++i) {
    const std::vector<size_t> ra = g.randomRoute(*g.indexOf(1), 35.0, a), rb = g.randomRoute(*g.indexOf(1), 35.0, b);
    EXPECT_EQ(ra, rb);
    for (size_t k = 1; k < ra.size(); ++k) {
      const auto& next = g.lanes()[ra[k - 1]].successors;
      EXPECT_NE(std::find(next.begin(), next.end(), ra[k]), next.end());
    }
    double length = 0;
    for (size_t k : ra) length += g.lanes()[k].length;
    EXPECT_TRUE(length >= 35.0 || g.lanes()[ra.back()].successors.empty());
  }
}

TEST(LaneGraph, BadLanesThrow) {
  VectorMap m = junction();
  m.laneSegments[2].leftLaneBoundary.clear();
  EXPECT_THROW(LaneGraph(m, {}, "junction"), Error);
  EXPECT_THROW(LaneGraph(junction(), {.centerlineSpacing = 0.0}, "junction"), Error);
}

TEST(LaneGraph, RealMapLanesLieOnTheDrivableArea) {
  std::filesystem::path vectorMap;
  for (const auto& e : std::filesystem::directory_iterator(test::sharedLog() / "map")) {
    if (e.path().filename().string().starts_with("log_map_archive_")) vectorMap = e.path();
  }
  const VectorMap map = readVectorMap(vectorMap);
  const LaneGraph g(map, {}, vectorMap.string());
  ASSERT_EQ(g.lanes().size(), 183u);
  const DrivableRaster raster = DrivableRaster::build(map, {}, "real");
  size_t points = 0, inside = 0, links = 0;
  for (const Lane& l : g.lanes()) {
    EXPECT_GT(l.length, 0.5) << l.id;
    for (const Eigen::Vector3d& p : l.centerline) {
      ++points;
      inside += raster.contains(p.head<2>());
    }
    for (size_t s : l.successors) {
      ++links;
      // A successor starts where its predecessor ends.
      EXPECT_LT((g.lanes()[s].centerline.front() - l.centerline.back()).head<2>().norm(), 0.5) << l.id << " -> " << g.lanes()[s].id;
      const auto& back = g.lanes()[s].predecessors;
      EXPECT_NE(std::find(back.begin(), back.end(), size_t(&l - g.lanes().data())), back.end());
    }
  }
  EXPECT_GT(double(inside), 0.99 * double(points));
  EXPECT_GT(links, 150u);
  // Routes of 200 m exist from most lanes of this small map.
  std::mt19937_64 rng(1);
  const std::vector<size_t> route = g.randomRoute(0, 200.0, rng);
  EXPECT_FALSE(route.empty());
  EXPECT_GT(g.reachable(0).size(), 1u);
}

}  // namespace
}  // namespace hdprior
