// The written map's changes on a town and a route through it: every kind appears, each is
// labelled with what the written map and the world hold, --map-change-within keeps them near
// the drive, the same seed gives the same changes, bad values are refused.
#include "engine/sim/map_change.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/sim/crosswalk_sites.h"
#include "engine/sim/drivable_lookup.h"
#include "town_route.h"

namespace hdprior {
namespace {

using Kind = MapChange::Kind;

// Town 7 and a 40 s route through it.
struct TownDrive {
  test::TownRoute townRoute{7, 3, 40.0};
  const TownMap& town = townRoute.town;
  const std::vector<Eigen::Vector2d>& drive = townRoute.path;
};

const TownDrive& townDrive() {
  static const TownDrive t;
  return t;
}

const DrivableArea* areaOf(const VectorMap& m, int64_t id) {
  for (const DrivableArea& a : m.drivableAreas)
    if (a.id == id) return &a;
  return nullptr;
}

const PedestrianCrossing* crossingOf(const VectorMap& m, int64_t id) {
  for (const PedestrianCrossing& c : m.pedestrianCrossings)
    if (c.id == id) return &c;
  return nullptr;
}

double distanceTo(const Eigen::Vector2d& p, const Ring2& line, bool closed) {
  return polylineDistance(std::span(&p, 1), line, closed);
}

// The lanes of `m` (their ids) that have `line` (either way round) as a boundary.
std::set<int64_t> lanesWithLine(const VectorMap& m, const Ring2& line) {
  std::set<int64_t> out;
  const auto same = [&](const Polyline3& b) {
    if (b.size() != line.size()) return false;
    bool forward = true, backward = true;
    for (size_t i = 0; i < b.size(); ++i) {
      forward &= (b[i].head<2>() - line[i]).norm() < 1e-9;
      backward &= (b[i].head<2>() - line[line.size() - 1 - i]).norm() < 1e-9;
    }
    return forward || backward;
  };
  for (const LaneSegment& l : m.laneSegments)
    if (same(l.leftLaneBoundary) || same(l.rightLaneBoundary)) out.insert(l.id);
  return out;
}

// A restriped line: the two lanes that share it in the world share it moved in the written map,
// 0.5-1.5 m to one side all along; the world (its paint) is untouched.
void expectMovedLaneLine(const VectorMap& world, const VectorMap& written, const MapChange& c) {
  const std::set<int64_t> sharing = lanesWithLine(world, c.worldStretch);
  EXPECT_EQ(sharing.size(), 2u);
  EXPECT_TRUE(sharing.count(c.id));
  EXPECT_EQ(lanesWithLine(written, c.changedStretch), sharing);
  EXPECT_TRUE(lanesWithLine(written, c.worldStretch).empty());
  EXPECT_GE(std::abs(c.offsetM), 0.5);
  EXPECT_LE(std::abs(c.offsetM), 1.5);
  ASSERT_EQ(c.changedStretch.size(), c.worldStretch.size());
  for (size_t i = 0; i + 1 < c.worldStretch.size(); ++i) {
    const Eigen::Vector2d left = leftNormal(c.worldStretch[i], c.worldStretch[i + 1]);
    const Eigen::Vector2d mid = 0.5 * (c.changedStretch[i] + c.changedStretch[i + 1]);
    EXPECT_NEAR((mid - c.worldStretch[i]).dot(left), c.offsetM, 0.05 * std::abs(c.offsetM));
  }
}

// What every change must satisfy, whatever its kind.
void expectLabelled(const VectorMap& world, const ChangedMap& changed, const MapChange& c) {
  const VectorMap& written = changed.map;
  switch (c.kind) {
    case Kind::Removed:
      ASSERT_TRUE(areaOf(world, c.id));
      EXPECT_FALSE(areaOf(written, c.id));
      EXPECT_EQ(c.worldOutline, ringOf(areaOf(world, c.id)->areaBoundary));
      EXPECT_TRUE(c.mapOutline.empty());
      break;
    case Kind::Shifted: {
      ASSERT_TRUE(areaOf(world, c.id) && areaOf(written, c.id));
      EXPECT_GE(c.shift.norm(), 1.0);
      EXPECT_LE(c.shift.norm(), 3.0);
      const Ring2 a = ringOf(areaOf(world, c.id)->areaBoundary), b = ringOf(areaOf(written, c.id)->areaBoundary);
      ASSERT_EQ(a.size(), b.size());
      for (size_t i = 0; i < a.size(); ++i) EXPECT_LT((b[i] - a[i] - c.shift).norm(), 1e-9);
      break;
    }
    case Kind::Added: {
      EXPECT_FALSE(areaOf(world, c.id));
      ASSERT_TRUE(areaOf(written, c.id));
      EXPECT_TRUE(c.worldOutline.empty());
      EXPECT_NEAR(std::abs(signedArea(c.mapOutline)), 8.0 * 15.0, 1e-6);
      Eigen::Vector2d centre = Eigen::Vector2d::Zero();
      for (const Eigen::Vector2d& p : c.mapOutline) centre += p / 4.0;
      EXPECT_FALSE(DrivableLookup(world).contains(centre));  // where the world has no road
      break;
    }
    case Kind::Narrowed: {
      ASSERT_TRUE(areaOf(world, c.id) && areaOf(written, c.id));
      const Ring2 a = ringOf(areaOf(world, c.id)->areaBoundary), b = ringOf(areaOf(written, c.id)->areaBoundary);
      EXPECT_EQ(b, c.mapOutline);
      EXPECT_TRUE(isSimpleRing(b));
      EXPECT_LE(c.offsetM, -1.0);
      EXPECT_GE(c.offsetM, -2.5);
      EXPECT_LT(std::abs(signedArea(b)), std::abs(signedArea(a)) - 1.0);  // less road in the map
      // The written side lies inside the world polygon, its inner vertices the stated amount off
      // the world's side.
      ASSERT_GE(c.changedStretch.size(), 2u);
      for (size_t i = 0; i < c.changedStretch.size(); ++i) {
        const Eigen::Vector2d& p = c.changedStretch[i];
        EXPECT_TRUE(ringContains(a, p) || distanceTo(p, a, true) < 1e-6);
        if (i > 0 && i + 1 < c.changedStretch.size()) {
          EXPECT_NEAR(distanceTo(p, c.worldStretch, false), -c.offsetM, 0.05 * -c.offsetM);
        }
      }
      break;
    }
    case Kind::KerbMoved: {
      ASSERT_TRUE(areaOf(world, c.id) && areaOf(written, c.id));
      const Ring2 a = ringOf(areaOf(world, c.id)->areaBoundary);
      EXPECT_TRUE(isSimpleRing(c.mapOutline));
      EXPECT_GE(std::abs(c.offsetM), 1.0);
      EXPECT_LE(std::abs(c.offsetM), 3.0);
      const double length = polylineLength2(c.worldStretch);
      EXPECT_GE(length, 10.0 - 1e-6);
      EXPECT_LE(length, 25.0 + 1e-6);
      EXPECT_LT(distanceTo(c.changedStretch.front(), a, true), 1e-6);  // tapered into the world's kerb
      EXPECT_LT(distanceTo(c.changedStretch.back(), a, true), 1e-6);
      double farthest = 0.0;
      for (const Eigen::Vector2d& p : c.changedStretch) {
        const double d = distanceTo(p, a, true);
        farthest = std::max(farthest, d);
        if (d > 0.1) {
          EXPECT_EQ(ringContains(a, p), c.offsetM < 0.0);  // inwards: inside the world's polygon
        }
      }
      EXPECT_NEAR(farthest, std::abs(c.offsetM), 0.05 * std::abs(c.offsetM));
      break;
    }
    case Kind::CrosswalkInserted: {
      EXPECT_FALSE(crossingOf(world, c.id));
      ASSERT_TRUE(crossingOf(written, c.id));
      EXPECT_EQ(crossingOutline(*crossingOf(written, c.id)), c.mapOutline);
      for (const PedestrianCrossing& w : world.pedestrianCrossings)
        EXPECT_GT(polylineDistance(c.mapOutline, crossingOutline(w), true), 0.5);
      const double depth = (c.mapOutline[3] - c.mapOutline[0]).norm(), width = (c.mapOutline[1] - c.mapOutline[0]).norm();
      EXPECT_NEAR(depth, 3.0, 1e-6);  // as the towns' crossings
      EXPECT_GE(width, 4.0);
      break;
    }
    case Kind::CrosswalkDeleted:
      ASSERT_TRUE(crossingOf(world, c.id));
      EXPECT_FALSE(crossingOf(written, c.id));
      EXPECT_EQ(c.worldOutline, crossingOutline(*crossingOf(world, c.id)));
      break;
    case Kind::LaneLineMoved:
      expectMovedLaneLine(world, written, c);
      break;
  }
}

TEST(MapChange, EveryKindAppearsAndIsLabelled) {
  const TownDrive& t = townDrive();
  std::map<Kind, int> seen;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const ChangedMap changed = changeMap(t.town.vectorMap, {0.5, 15.0}, t.drive, seed);
    for (const MapChange& c : changed.changes) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", change of id " + std::to_string(c.id));
      ++seen[c.kind];
      expectLabelled(t.town.vectorMap, changed, c);
      EXPECT_LE(c.routeDistanceM, 15.0 + 1e-6);
    }
  }
  for (Kind k : {Kind::Removed, Kind::Shifted, Kind::Added, Kind::Narrowed, Kind::KerbMoved, Kind::CrosswalkInserted,
                 Kind::CrosswalkDeleted, Kind::LaneLineMoved})
    EXPECT_GT(seen[k], 0) << "kind " << int(k);
  for (const auto& [k, n] : seen) std::printf("[ info ] kind %d: %d changes\n", int(k), n);
}

TEST(MapChange, WithinRestrictsTheChangesToElementsNearTheDrive) {
  const TownDrive& t = townDrive();
  const ChangedMap anywhere = changeMap(t.town.vectorMap, {0.3, std::nullopt}, t.drive, 5);
  const ChangedMap near = changeMap(t.town.vectorMap, {0.3, 15.0}, t.drive, 5);
  enum Element { Area, Crossing, Line };
  const auto count = [](const ChangedMap& m, Element element, double within) {
    return std::count_if(m.changes.begin(), m.changes.end(), [&](const MapChange& c) {
      const Element e = c.crossing() ? Crossing : c.laneLine() ? Line : Area;
      return e == element && c.routeDistanceM <= within;
    });
  };
  // Anywhere: 30 % of the town's polygons, most of them far from the drive.
  EXPECT_EQ(count(anywhere, Area, 1e9), std::llround(0.3 * double(t.town.vectorMap.drivableAreas.size())));
  EXPECT_LT(count(anywhere, Area, 15.0), count(anywhere, Area, 1e9) / 2);
  EXPECT_LT(count(anywhere, Line, 15.0), count(anywhere, Line, 1e9) / 2);
  // Near: every change within 15 m, as many as 30 % of the polygons whose outline is near.
  size_t eligible = 0;
  for (const DrivableArea& a : t.town.vectorMap.drivableAreas)
    eligible += polylineDistance(t.drive, ringOf(a.areaBoundary), true) <= 15.0;
  EXPECT_EQ(count(near, Area, 15.0), std::max<long>(1, std::llround(0.3 * double(eligible))));
  EXPECT_EQ(count(near, Area, 1e9), count(near, Area, 15.0));
  for (Element e : {Crossing, Line}) {
    EXPECT_GE(count(near, e, 15.0), 1);
    EXPECT_EQ(count(near, e, 1e9), count(near, e, 15.0));
  }
}

TEST(MapChange, TheSameSeedGivesTheSameChanges) {
  const TownDrive& t = townDrive();
  const MapChangeOptions o{0.4, 20.0};
  const std::string a = mapChangesToJson(o, changeMap(t.town.vectorMap, o, t.drive, 9).changes);
  EXPECT_EQ(a, mapChangesToJson(o, changeMap(t.town.vectorMap, o, t.drive, 9).changes));
  EXPECT_NE(a, mapChangesToJson(o, changeMap(t.town.vectorMap, o, t.drive, 10).changes));
}

TEST(MapChange, NothingChangesAtFractionZero) {
  const TownDrive& t = townDrive();
  const ChangedMap m = changeMap(t.town.vectorMap, {0.0, 10.0}, t.drive, 1);
  EXPECT_TRUE(m.changes.empty());
  EXPECT_EQ(vectorMapToJson(m.map), vectorMapToJson(t.town.vectorMap));
}

TEST(MapChange, TheSideCarLabelsEachChangeInTbVsVocabulary) {
  const TownDrive& t = townDrive();
  const MapChangeOptions o{0.5, 15.0};
  std::set<std::string> changes;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const auto j = nlohmann::json::parse(mapChangesToJson(o, changeMap(t.town.vectorMap, o, t.drive, seed).changes));
    EXPECT_EQ(j["fraction"], 0.5);
    EXPECT_EQ(j["within_m"], 15.0);
    for (const auto& c : j["changes"]) {
      const std::string change = c["change"], element = c["element"], tbv = c["tbv_change"];
      changes.insert(change);
      EXPECT_TRUE(c["id"].is_number_integer());
      EXPECT_LE(double(c["route_distance_m"]), 15.0 + 1e-6);
      const bool crossing = change.rfind("crosswalk_", 0) == 0;
      EXPECT_EQ(element, crossing ? "pedestrian_crossing" : change == "lane_line_moved" ? "lane_boundary" : "drivable_area");
      EXPECT_EQ(tbv, change == "crosswalk_inserted" ? "insert_crosswalk"
                     : change == "crosswalk_deleted" ? "delete_crosswalk"
                                                     : "lane_geometry_change");
      const bool line = change == "lane_line_moved";
      EXPECT_EQ(c.contains("world_outline"), !line && change != "added" && change != "crosswalk_inserted") << change;
      EXPECT_EQ(c.contains("map_outline"), !line && change != "removed" && change != "crosswalk_deleted") << change;
      EXPECT_EQ(c.contains("changed_stretch"), change == "narrowed" || change == "kerb_moved" || change == "lane_line_moved") << change;
      EXPECT_EQ(c.contains("shift_m"), change == "shifted") << change;
      if (c.contains("world_outline")) {
        EXPECT_EQ(c["world_outline"][0].size(), 2u);
      }
    }
  }
  EXPECT_EQ(changes.size(), 8u);
  EXPECT_TRUE(nlohmann::json::parse(mapChangesToJson({0.2, std::nullopt}, {}))["within_m"].is_null());
}

TEST(MapChange, RestripingMovesAShareOfTheSharedLinesAndNeverBothLinesOfALane) {
  const TownDrive& t = townDrive();
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const ChangedMap changed = changeMap(t.town.vectorMap, {0.5, 15.0}, t.drive, seed);
    std::map<int64_t, int> moves;  // lane id -> its lines moved
    size_t moved = 0;
    for (const MapChange& c : changed.changes) {
      if (!c.laneLine()) continue;
      ++moved;
      for (int64_t id : lanesWithLine(t.town.vectorMap, c.worldStretch)) ++moves[id];
    }
    EXPECT_GE(moved, 2u) << "seed " << seed;
    for (const auto& [id, n] : moves) EXPECT_EQ(n, 1) << "lane " << id << ", seed " << seed;
  }
}

TEST(MapChange, BadValuesAreRefused) {
  const TownDrive& t = townDrive();
  for (double f : {-0.1, 1.5, std::nan("")}) EXPECT_THROW(changeMap(t.town.vectorMap, {f, std::nullopt}, t.drive, 1), Error);
  for (double m : {-1.0, std::numeric_limits<double>::infinity(), std::nan("")})
    EXPECT_THROW(changeMap(t.town.vectorMap, {0.2, m}, t.drive, 1), Error);
}

TEST(CrosswalkSites, AcrossStreetsNearJunctionsWhereTheWorldHasNone) {
  const VectorMap& world = townDrive().town.vectorMap;
  const std::vector<PedestrianCrossing> sites = crosswalkSites(world);
  ASSERT_GT(sites.size(), 10u);
  const DrivableLookup drivable(world);
  for (const PedestrianCrossing& s : sites) {
    const Ring2 outline = crossingOutline(s);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& p : outline) centre += p / 4.0;
    EXPECT_TRUE(drivable.contains(centre));
    for (const PedestrianCrossing& w : world.pedestrianCrossings) EXPECT_GE(polylineDistance(outline, crossingOutline(w), true), 1.0);
  }
}

}  // namespace
}  // namespace hdprior
