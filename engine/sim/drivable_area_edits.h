#pragma once
#include <optional>
#include <random>
#include <span>

#include "engine/io/vector_map.h"
#include "engine/sim/drivable_lookup.h"
#include "engine/sim/map_change.h"

namespace hdprior {

// What a drivable-area change is made in: the world, the drive, how near it must be, the
// random draws.
struct EditContext {
  const DrivableLookup& world;
  std::span<const Eigen::Vector2d> drive;  // thinned
  double withinM;                          // +infinity: anywhere
  std::mt19937_64& rng;
};

// One change of `kind` (Removed .. KerbMoved) to `area` (the world's polygon). Fills the
// change's geometry; `written` becomes the written polygon (Shifted, Narrowed, KerbMoved) or the
// new one (Added, with newId). nullopt when this kind does not fit the polygon.
std::optional<MapChange> editDrivableArea(MapChange::Kind kind, const DrivableArea& area, int64_t newId,
                                          EditContext& context, DrivableArea& written);

}  // namespace hdprior
