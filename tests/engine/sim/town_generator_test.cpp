// Procedural towns: the map passes the same checks as a real map (exact union area, lane
// graph connectivity, lanes on the road), has the features the simulator issue asks for,
// is deterministic by seed and is written in the Argoverse 2 layout.
#include "engine/sim/town_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

// Boost.Geometry's rescaling policy trips GCC 12's -Wmaybe-uninitialized in its own code.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#pragma GCC diagnostic pop

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/npy.h"
#include "engine/io/sim2.h"
#include "engine/io/vector_map.h"
#include "engine/map/hd_map.h"
#include "engine/sim/town_writer.h"

namespace hdprior {
namespace {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;
using BMultiPolygon = bg::model::multi_polygon<BPolygon>;

constexpr uint64_t kSeed = 7;

// One town shared by the tests (generation takes most of a second).
const TownMap& town() {
  static const TownMap t = generateTown(TownOptions{}, kSeed);
  return t;
}

GroundHeight groundOf(const TownMap& t) { return GroundHeight::fromNpy(t.groundHeight, t.imgSim2City, "town"); }

// A 0.5 m raster (instead of 0.1 m) keeps the 1.4 km town's checks fast; the union-area
// tolerance still holds with room to spare.
const HdMap& hdMap() {
  static const HdMap m = [] {
    HdMapOptions options;
    options.raster.resolution = 0.5;
    options.ndtCellSizes = {2.0};
    options.boundaryDistance = false;
    return HdMap::build(town().vectorMap, groundOf(town()), options, "town");
  }();
  return m;
}

TEST(TownGenerator, DrivableRasterAreaMatchesTheExactPolygonUnion) {
  BMultiPolygon unionAll;
  for (const DrivableArea& a : town().vectorMap.drivableAreas) {
    BPolygon p;
    for (const Eigen::Vector3d& v : a.areaBoundary) bg::append(p.outer(), BPoint(v.x(), v.y()));
    bg::correct(p);
    ASSERT_TRUE(bg::is_valid(p)) << "drivable area " << a.id;
    BMultiPolygon next;
    bg::union_(unionAll, p, next);
    unionAll = std::move(next);
  }
  const double exact = bg::area(unionAll);
  EXPECT_NEAR(hdMap().drivable().area(), exact, 0.005 * exact);
  // Several polygons, like real maps: one per street and one per junction, all joined.
  EXPECT_EQ(town().vectorMap.drivableAreas.size(), town().streets.size() + town().nodes.size());
  EXPECT_EQ(unionAll.size(), 1u) << "the road network is one connected region";
}

TEST(TownGenerator, EveryLaneIsReachableFromEveryLane) {
  const LaneGraph& g = hdMap().laneGraph();
  ASSERT_GT(g.lanes().size(), 100u);
  EXPECT_EQ(g.droppedLinks(), 0u);
  EXPECT_EQ(g.reachable(0).size(), g.lanes().size());
  EXPECT_EQ(g.reachable(g.lanes().size() / 2).size(), g.lanes().size());
  EXPECT_EQ(g.reachable(g.lanes().size() - 1).size(), g.lanes().size());
  for (const LaneSegment& l : town().vectorMap.laneSegments) EXPECT_EQ(l.laneType, "VEHICLE");
  EXPECT_FALSE(town().vectorMap.pedestrianCrossings.empty());
}

TEST(TownGenerator, LaneCenterlinesLieOnTheDrivableArea) {
  size_t inside = 0, total = 0;
  for (const Lane& lane : hdMap().laneGraph().lanes()) {
    for (const Eigen::Vector3d& p : lane.centerline) {
      ++total;
      if (hdMap().drivable().contains(p.head<2>())) ++inside;
    }
  }
  EXPECT_GE(double(inside), 0.99 * double(total)) << inside << " of " << total;
}

TEST(TownGenerator, HasTheRequiredStreetNetwork) {
  Eigen::Vector2d lo = town().nodes.front().position, hi = lo;
  for (const TownNode& n : town().nodes) lo = lo.cwiseMin(n.position), hi = hi.cwiseMax(n.position);
  EXPECT_GE(hi.x() - lo.x(), 1000.0);
  EXPECT_GE(hi.y() - lo.y(), 1000.0);

  double minWidth = 1e9, maxWidth = 0.0, longestCorridor = 0.0;
  bool curved = false, straight = false;
  for (const TownStreet& s : town().streets) {
    minWidth = std::min(minWidth, s.width);
    maxWidth = std::max(maxWidth, s.width);
    (s.curved ? curved : straight) = true;
    // A corridor street: no junction along it, from the grid out to a bend of the loop.
    if (s.corridor) longestCorridor = std::max(longestCorridor, s.length);
  }
  EXPECT_DOUBLE_EQ(minWidth, 6.0);
  EXPECT_DOUBLE_EQ(maxWidth, 20.0);
  EXPECT_TRUE(curved);
  EXPECT_TRUE(straight);
  EXPECT_GE(longestCorridor, 300.0);
  int t = 0, x = 0;
  for (const TownNode& n : town().nodes) {
    if (n.degree == 3) ++t;
    if (n.degree == 4) ++x;
  }
  EXPECT_GE(t, 1);
  EXPECT_GE(x, 1);
  // The lanes: one or two per direction, by width.
  for (const TownStreet& s : town().streets) EXPECT_EQ(s.lanesPerDirection, s.width >= 11.0 ? 2 : 1);
}

TEST(TownGenerator, HillsStayWithinTheGradeLimit) {
  // Grade along each lane over 5 m baselines of the float16 raster (its 2 cm steps would
  // make 1 m baselines noisy), and of the terrain itself.
  const GroundHeight ground = groundOf(town());
  double maxRaster = 0.0, maxTerrain = 0.0;
  for (const Lane& lane : hdMap().laneGraph().lanes()) {
    const Polyline3 line = resampleByArcLength(lane.centerline, std::max<size_t>(2, size_t(lane.length / 5.0) + 1));
    for (size_t i = 1; i < line.size(); ++i) {
      const double run = (line[i] - line[i - 1]).head<2>().norm();
      if (run < 2.0) continue;
      const double h0 = ground.bilinearAt(line[i - 1].head<2>()), h1 = ground.bilinearAt(line[i].head<2>());
      ASSERT_TRUE(std::isfinite(h0) && std::isfinite(h1));
      maxRaster = std::max(maxRaster, std::abs(h1 - h0) / run);
      const Eigen::Vector2d dir = (line[i] - line[i - 1]).head<2>() / run;
      maxTerrain = std::max(maxTerrain, std::abs(town().terrain.gradient(line[i].head<2>()).dot(dir)));
    }
  }
  // Up to 8 % (the default hillGrade) and the lanes do climb real hills: over 5 %.
  EXPECT_LE(maxTerrain, 0.0805);
  EXPECT_LE(maxRaster, 0.085);  // + float16 steps over 5 m
  EXPECT_GT(maxRaster, 0.05);
  EXPECT_GT(maxTerrain, 0.05);
  std::printf("[ info ] max grade along lanes: raster %.4f, terrain %.4f\n", maxRaster, maxTerrain);
}

TEST(TownGenerator, GroundHeightIsGivenNearTheRoadAndNaNFarFromIt) {
  const GroundHeight ground = groundOf(town());
  EXPECT_EQ(town().groundHeight.dtype, NpyDtype::Float16);
  EXPECT_DOUBLE_EQ(town().imgSim2City.s, 1.0 / 0.3);
  EXPECT_TRUE(town().imgSim2City.R.isIdentity());
  // Finite on every drivable cell, NaN wherever the distance to the road exceeds ~5 m.
  const DrivableRaster& d = hdMap().drivable();
  const GridGeometry& g = d.geometry();
  for (int row = 0; row < g.rows; row += 7) {
    for (int col = 0; col < g.cols; col += 7) {
      const Eigen::Vector2d p = g.cellCentre(col, row);
      if (d.drivable(col, row)) {
        EXPECT_TRUE(std::isfinite(ground.heightAt(p))) << p.transpose();
        continue;
      }
      // Far from the road: no drivable cell within 5.6 m (a pixel diagonal past 5 m).
      bool nearRoad = false;
      const int reach = int(std::ceil(5.6 / g.resolution));
      for (int dr = -reach; dr <= reach && !nearRoad; ++dr)
        for (int dc = -reach; dc <= reach && !nearRoad; ++dc)
          nearRoad = std::hypot(dr, dc) * g.resolution <= 5.6 && d.drivable(col + dc, row + dr);
      if (!nearRoad) {
        EXPECT_TRUE(std::isnan(ground.heightAt(p))) << p.transpose();
      }
    }
  }
}

TEST(TownGenerator, OtherSeedsAreConnectedTooAndHaveTAndXJunctions) {
  for (uint64_t seed : {1u, 16u}) {
    const TownMap t = generateTown(TownOptions{}, seed);
    const LaneGraph g(t.vectorMap, {}, "town");
    EXPECT_EQ(g.reachable(0).size(), g.lanes().size()) << "seed " << seed;
    EXPECT_EQ(g.reachable(g.lanes().size() - 1).size(), g.lanes().size()) << "seed " << seed;
    int junctions3 = 0, junctions4 = 0;
    for (const TownNode& n : t.nodes) {
      if (n.degree == 3) ++junctions3;
      if (n.degree == 4) ++junctions4;
    }
    EXPECT_GE(junctions3, 1) << "seed " << seed;
    EXPECT_GE(junctions4, 1) << "seed " << seed;
  }
}

TEST(TownGenerator, IsDeterministicBySeed) {
  const TownMap again = generateTown(TownOptions{}, kSeed);
  EXPECT_EQ(vectorMapToJson(again.vectorMap), vectorMapToJson(town().vectorMap));
  EXPECT_EQ(serializeNpy(again.groundHeight), serializeNpy(town().groundHeight));
  EXPECT_EQ(sim2ToJson(again.imgSim2City), sim2ToJson(town().imgSim2City));
  const TownMap other = generateTown(TownOptions{}, kSeed + 1);
  EXPECT_NE(vectorMapToJson(other.vectorMap), vectorMapToJson(town().vectorMap));
  EXPECT_NE(serializeNpy(other.groundHeight), serializeNpy(town().groundHeight));
}

TEST(TownGenerator, RejectsBadOptions) {
  TownOptions o;
  o.maxRoadWidth = 3.0;
  EXPECT_THROW(generateTown(o, 1), Error);
  o = {};
  o.gridCols = 1;
  EXPECT_THROW(generateTown(o, 1), Error);
  o = {};
  o.hillGrade = -0.1;
  EXPECT_THROW(generateTown(o, 1), Error);
}

TEST(TownWriter, WritesArgoverseMapFilesThatReadBackEqual) {
  const std::filesystem::path dir = std::filesystem::path(HDPRIOR_TEST_OUTPUT) / "town_writer" / "log_town_7";
  std::filesystem::remove_all(dir);
  writeTownMap(dir, "log_town_7", "SIM", town());
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir / "map")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  ASSERT_EQ(names.size(), 3u);
  // The names ArgoverseLog's discovery looks for (prefix / infix and extension).
  EXPECT_EQ(names[0], "log_map_archive_log_town_7____SIM_city_7.json");
  EXPECT_EQ(names[1], "log_town_7___img_Sim2_city.json");
  EXPECT_EQ(names[2], "log_town_7_ground_height_surface____SIM.npy");

  const VectorMap map = readVectorMap(dir / "map" / names[0]);
  EXPECT_EQ(vectorMapToJson(map), vectorMapToJson(town().vectorMap));
  const NpyArray npy = readNpy(dir / "map" / names[2]);
  EXPECT_EQ(npy.dtype, NpyDtype::Float16);
  EXPECT_EQ(npy.shape, town().groundHeight.shape);
  EXPECT_EQ(serializeNpy(npy), serializeNpy(town().groundHeight));
  const Sim2 sim2 = readSim2(dir / "map" / names[1]);
  EXPECT_TRUE(sim2.R.isApprox(town().imgSim2City.R));
  EXPECT_NEAR(sim2.s, town().imgSim2City.s, 1e-12);
  EXPECT_TRUE(sim2.t.isApprox(town().imgSim2City.t, 1e-12));
  // And the engine loads it as a log's map.
  LogMapFiles files{dir / "map" / names[0], dir / "map" / names[2], dir / "map" / names[1]};
  HdMapOptions options;
  options.raster.resolution = 0.5;
  options.ndtCellSizes = {2.0};
  options.boundaryDistance = false;
  const HdMap loaded = HdMap::load(files, options);
  EXPECT_EQ(loaded.laneGraph().lanes().size(), town().vectorMap.laneSegments.size());
  EXPECT_TRUE(loaded.hasGroundHeight());
}

}  // namespace
}  // namespace hdprior
