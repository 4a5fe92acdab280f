#include "engine/sim/map_change.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/sim/crosswalk_sites.h"
#include "engine/sim/drivable_area_edits.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;
using Kind = MapChange::Kind;

// How many of `eligible` elements change: the share, at least one when there is any.
size_t changeCount(double fraction, size_t eligible) {
  if (fraction <= 0.0 || eligible == 0) return 0;
  return std::max<size_t>(1, size_t(std::llround(fraction * double(eligible))));
}

Ring2 thinned(std::span<const Vec2> drive, double spacing) {
  Ring2 out;
  for (const Vec2& p : drive)
    if (out.empty() || (p - out.back()).norm() >= spacing) out.push_back(p);
  if (!drive.empty() && (drive.back() - out.back()).norm() > 0.0) out.push_back(drive.back());
  return out;
}

void changeDrivableAreas(const VectorMap& world, const MapChangeOptions& o, const Ring2& drive, uint64_t seed,
                         ChangedMap& out) {
  const double within = o.withinM.value_or(std::numeric_limits<double>::infinity());
  const size_t n = world.drivableAreas.size();
  std::vector<size_t> eligible;
  for (size_t i = 0; i < n; ++i)
    if (!o.withinM || polylineDistance(drive, ringOf(world.drivableAreas[i].areaBoundary), true) <= within)
      eligible.push_back(i);
  std::mt19937_64 rng(seed ^ 0x3a9c4a11ULL);
  std::shuffle(eligible.begin(), eligible.end(), rng);
  eligible.resize(changeCount(o.fraction, eligible.size()));
  std::sort(eligible.begin(), eligible.end());
  int64_t nextId = 0;
  for (const DrivableArea& a : world.drivableAreas) nextId = std::max(nextId, a.id + 1);

  const DrivableLookup lookup(world);
  EditContext context{lookup, drive, within, rng};
  std::vector<bool> removed(n, false);
  std::vector<DrivableArea> added;
  for (size_t i : eligible) {
    // Another kind when the one drawn does not fit the polygon (Removed always does).
    const int first = std::uniform_int_distribution<int>(0, 4)(rng);
    for (int k = 0; k < 5; ++k) {
      const Kind kind = Kind((first + k) % 5);
      DrivableArea written;
      auto change = editDrivableArea(kind, world.drivableAreas[i], nextId, context, written);
      if (!change) continue;
      if (kind == Kind::Removed) removed[i] = true;
      else if (kind == Kind::Added) added.push_back(written), ++nextId;
      else out.map.drivableAreas[i] = written;
      out.changes.push_back(std::move(*change));
      break;
    }
  }
  std::vector<DrivableArea> kept;
  for (size_t i = 0; i < n; ++i)
    if (!removed[i]) kept.push_back(out.map.drivableAreas[i]);
  kept.insert(kept.end(), added.begin(), added.end());
  std::sort(kept.begin(), kept.end(), [](const DrivableArea& a, const DrivableArea& b) { return a.id < b.id; });
  out.map.drivableAreas = std::move(kept);
  if (out.map.drivableAreas.empty()) throw Error("option --map-change", "would remove every drivable area");
}

void changeCrossings(const VectorMap& world, const MapChangeOptions& o, const Ring2& drive, uint64_t seed,
                     ChangedMap& out) {
  const auto near = [&](const PedestrianCrossing& c) {
    return !o.withinM || polylineDistance(drive, crossingOutline(c), true) <= *o.withinM;
  };
  std::vector<size_t> deletable;
  for (size_t i = 0; i < world.pedestrianCrossings.size(); ++i)
    if (near(world.pedestrianCrossings[i])) deletable.push_back(i);
  std::vector<PedestrianCrossing> sites = crosswalkSites(world);
  std::erase_if(sites, [&](const PedestrianCrossing& c) { return !near(c); });
  size_t count = changeCount(o.fraction, deletable.size());
  if (o.fraction > 0.0 && count == 0 && !sites.empty()) count = 1;
  std::mt19937_64 rng(seed ^ 0x7c1d05a3ULL);
  std::shuffle(deletable.begin(), deletable.end(), rng);
  std::shuffle(sites.begin(), sites.end(), rng);
  int64_t nextId = 1;
  for (const PedestrianCrossing& c : world.pedestrianCrossings) nextId = std::max(nextId, c.id + 1);
  std::vector<int64_t> deleted;
  for (size_t k = 0; k < count && (!deletable.empty() || !sites.empty()); ++k) {
    const bool insert = std::uniform_int_distribution<int>(0, 1)(rng) == 1 ? !sites.empty() : deletable.empty();
    MapChange change;
    if (insert) {
      PedestrianCrossing c = sites.back();
      sites.pop_back();
      c.id = nextId++;
      change.kind = Kind::CrosswalkInserted;
      change.id = c.id;
      change.mapOutline = crossingOutline(c);
      out.map.pedestrianCrossings.push_back(std::move(c));
    } else {
      const PedestrianCrossing& c = world.pedestrianCrossings[deletable.back()];
      deletable.pop_back();
      change.kind = Kind::CrosswalkDeleted;
      change.id = c.id;
      change.worldOutline = crossingOutline(c);
      deleted.push_back(c.id);
    }
    out.changes.push_back(std::move(change));
  }
  std::erase_if(out.map.pedestrianCrossings,
                [&](const PedestrianCrossing& c) { return std::find(deleted.begin(), deleted.end(), c.id) != deleted.end(); });
  std::sort(out.map.pedestrianCrossings.begin(), out.map.pedestrianCrossings.end(),
            [](const PedestrianCrossing& a, const PedestrianCrossing& b) { return a.id < b.id; });
}

// The line moved `offset` metres to its left, vertex by vertex (along the mean of the adjacent
// segments' normals).
Polyline3 movedLine(const Polyline3& line, double offset) {
  Polyline3 out = line;
  for (size_t i = 0; i < line.size(); ++i) {
    const Vec2 a = line[i == 0 ? 0 : i - 1].head<2>(), b = line[i + 1 < line.size() ? i + 1 : i].head<2>();
    out[i].head<2>() += offset * leftNormal(a, b);
  }
  return out;
}

Ring2 plan(const Polyline3& line) {
  Ring2 out;
  for (const Eigen::Vector3d& p : line) out.push_back(p.head<2>());
  return out;
}

// A painted line outside intersections that two lanes share: its key, the world's polyline and
// the first lane that has it.
struct SharedLine {
  LaneLineKey key;
  const Polyline3* line = nullptr;
  int64_t lane = 0;
  std::vector<int64_t> lanes;  // the two lanes that share it
};

std::vector<SharedLine> sharedPaintedLines(const VectorMap& world) {
  std::map<LaneLineKey, SharedLine> byKey;
  for (const LaneSegment& lane : world.laneSegments) {
    if (lane.isIntersection) continue;
    for (bool left : {true, false}) {
      const Polyline3& line = left ? lane.leftLaneBoundary : lane.rightLaneBoundary;
      if (line.size() < 2 || !isPaintedMark(left ? lane.leftLaneMarkType : lane.rightLaneMarkType)) continue;
      SharedLine& s = byKey.try_emplace(laneLineKey(line), SharedLine{laneLineKey(line), &line, lane.id, {}}).first->second;
      s.lanes.push_back(lane.id);
    }
  }
  std::vector<SharedLine> out;
  for (auto& [key, s] : byKey)
    if (s.lanes.size() == 2) out.push_back(std::move(s));
  return out;
}

// Draws the line `offset` metres to its left in every lane of `map` that has it.
MapChange moveLaneLine(const SharedLine& s, double offset, VectorMap& map) {
  const Polyline3 moved = movedLine(*s.line, offset), reversed(moved.rbegin(), moved.rend());
  for (LaneSegment& l : map.laneSegments)
    for (Polyline3* b : {&l.leftLaneBoundary, &l.rightLaneBoundary})
      if (b->size() >= 2 && laneLineKey(*b) == s.key) *b = (*b == *s.line) ? moved : reversed;
  MapChange change;
  change.kind = Kind::LaneLineMoved;
  change.id = s.lane;
  change.changedStretch = plan(moved);
  change.worldStretch = plan(*s.line);
  change.offsetM = offset;
  return change;
}

void changeLaneLines(const VectorMap& world, const MapChangeOptions& o, const Ring2& drive, uint64_t seed,
                     ChangedMap& out) {
  std::vector<SharedLine> eligible = sharedPaintedLines(world);
  std::erase_if(eligible, [&](const SharedLine& s) { return o.withinM && polylineDistance(drive, plan(*s.line), false) > *o.withinM; });
  std::mt19937_64 rng(seed ^ 0x51e4b0d7ULL);
  std::shuffle(eligible.begin(), eligible.end(), rng);
  size_t count = changeCount(o.fraction, eligible.size());
  std::set<int64_t> narrowed;  // lanes with a line moved: their other line stays, or the lane would vanish
  for (const SharedLine& s : eligible) {
    if (count == 0) break;
    if (std::any_of(s.lanes.begin(), s.lanes.end(), [&](int64_t id) { return narrowed.count(id) > 0; })) continue;
    narrowed.insert(s.lanes.begin(), s.lanes.end());
    --count;
    const double offset = (std::uniform_int_distribution<int>(0, 1)(rng) ? 1.0 : -1.0) *
                          std::uniform_real_distribution<double>(0.5, 1.5)(rng);
    out.changes.push_back(moveLaneLine(s, offset, out.map));
  }
}

// Nearest distance from the drive to what differs: the changed stretch and where it is in the
// world, or the element's outlines.
double routeDistance(const Ring2& drive, const MapChange& c) {
  if (!c.changedStretch.empty())
    return std::min(polylineDistance(drive, c.changedStretch, false), polylineDistance(drive, c.worldStretch, false));
  return std::min(polylineDistance(drive, c.worldOutline, true), polylineDistance(drive, c.mapOutline, true));
}

const char* kindName(Kind k) {
  switch (k) {
    case Kind::Removed: return "removed";
    case Kind::Shifted: return "shifted";
    case Kind::Added: return "added";
    case Kind::Narrowed: return "narrowed";
    case Kind::KerbMoved: return "kerb_moved";
    case Kind::CrosswalkInserted: return "crosswalk_inserted";
    case Kind::CrosswalkDeleted: return "crosswalk_deleted";
    case Kind::LaneLineMoved: return "lane_line_moved";
  }
  return "";
}

nlohmann::json points(const Ring2& ring) {
  nlohmann::json j = nlohmann::json::array();
  for (const Vec2& p : ring) j.push_back({p.x(), p.y()});
  return j;
}

}  // namespace

ChangedMap changeMap(const VectorMap& world, const MapChangeOptions& options, std::span<const Vec2> drive, uint64_t seed) {
  if (!(options.fraction >= 0.0 && options.fraction <= 1.0)) throw Error("option --map-change", "must be between 0 and 1");
  if (options.withinM && !(*options.withinM >= 0.0 && std::isfinite(*options.withinM)))
    throw Error("option --map-change-within", "must be a distance of at least 0 m");
  ChangedMap out{world, {}};
  if (options.fraction == 0.0) return out;
  const Ring2 path = thinned(drive, 0.5);
  changeDrivableAreas(world, options, path, seed, out);
  changeCrossings(world, options, path, seed, out);
  changeLaneLines(world, options, path, seed, out);
  for (MapChange& c : out.changes) c.routeDistanceM = routeDistance(path, c);
  return out;
}

std::string mapChangesToJson(const MapChangeOptions& options, const std::vector<MapChange>& changes) {
  nlohmann::json j;
  j["fraction"] = options.fraction;
  j["within_m"] = options.withinM ? nlohmann::json(*options.withinM) : nlohmann::json(nullptr);
  j["changes"] = nlohmann::json::array();
  for (const MapChange& c : changes) {
    nlohmann::json e = {{"element", c.crossing() ? "pedestrian_crossing" : c.laneLine() ? "lane_boundary" : "drivable_area"},
                        {"id", c.id},
                        {"change", kindName(c.kind)},
                        {"tbv_change", c.kind == Kind::CrosswalkInserted  ? "insert_crosswalk"
                                       : c.kind == Kind::CrosswalkDeleted ? "delete_crosswalk"
                                                                          : "lane_geometry_change"}};
    if (!c.worldOutline.empty()) e["world_outline"] = points(c.worldOutline);
    if (!c.mapOutline.empty()) e["map_outline"] = points(c.mapOutline);
    if (!c.changedStretch.empty()) {
      e["changed_stretch"] = points(c.changedStretch);
      e["offset_m"] = c.offsetM;
    }
    if (c.kind == Kind::Shifted) e["shift_m"] = {c.shift.x(), c.shift.y()};
    e["route_distance_m"] = c.routeDistanceM;
    j["changes"].push_back(std::move(e));
  }
  return j.dump(2) + "\n";
}

}  // namespace hdprior
