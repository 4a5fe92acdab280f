#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/polygon2d.h"
#include "engine/io/vector_map.h"

namespace hdprior {

struct MapChangeOptions {
  double fraction = 0.0;          // share of the eligible drivable polygons (and crossings) changed, 0..1
  std::optional<double> withinM;  // eligible: outline within this many metres of the drive; nullopt: anywhere
};

// One difference between the written map and the world that was ray-cast.
struct MapChange {
  enum class Kind { Removed, Shifted, Added, Narrowed, KerbMoved, CrosswalkInserted, CrosswalkDeleted, LaneLineMoved };
  Kind kind = Kind::Removed;
  int64_t id = 0;                   // the world's id (Removed, CrosswalkDeleted) or the written map's (LaneLineMoved: the first lane whose boundary it is)
  Ring2 worldOutline, mapOutline;   // empty where the element is absent
  Ring2 changedStretch;             // Narrowed, KerbMoved, LaneLineMoved: the written boundary that differs ...
  Ring2 worldStretch;               // ... and where it is in the world
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // Shifted: metres, city frame
  // Narrowed, KerbMoved: how far the boundary moved, + outwards; LaneLineMoved: + to the left of
  // changedStretch's direction.
  double offsetM = 0.0;
  double routeDistanceM = 0.0;      // nearest distance from the drive to what differs
  bool crossing() const { return kind == Kind::CrosswalkInserted || kind == Kind::CrosswalkDeleted; }
  bool laneLine() const { return kind == Kind::LaneLineMoved; }
};

struct ChangedMap {
  VectorMap map;
  std::vector<MapChange> changes;
};

// The TbV theme: a map that is out of date. Of the eligible drivable polygons (all, or those
// whose outline passes within options.withinM of `drive`), a share `fraction` (at least one when
// fraction > 0) is chosen by seed and each removed, shifted by 1-3 m, given a new 8 m x 15 m
// polygon beside it where the world has no road, narrowed (one side moved 1-2.5 m inwards), or
// has a 10-25 m stretch of kerb moved 1-3 m in or out (tapered over 3 m). Of the eligible
// crossings as many again in share (at least one when any is eligible or could be inserted) are
// deleted or inserted (crosswalkSites), even odds. Of the eligible painted lane lines that two
// lanes share (not in an intersection), as many again in share are moved sideways by 0.5-1.5 m
// in the written map, as a restriping that narrows one lane and widens the other; the world keeps
// its paint. Throws Error for a fraction outside [0, 1] or a negative distance.
ChangedMap changeMap(const VectorMap& world, const MapChangeOptions& options, std::span<const Eigen::Vector2d> drive,
                     uint64_t seed);
// The side-car map_change.json (docs/formats.md).
std::string mapChangesToJson(const MapChangeOptions& options, const std::vector<MapChange>& changes);

}  // namespace hdprior
