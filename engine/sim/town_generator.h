#pragma once
#include <cstdint>

#include "engine/sim/town_map.h"
#include "engine/sim/town_options.h"

namespace hdprior {

// A procedural town, deterministic by seed: a jittered grid of junctions with some inner
// streets removed (T junctions), some bent, some grid lines extended into long corridor
// loops; one width per street line (1-2 lanes per direction); hills from a HeightField.
// Drivable areas: one polygon per street and one per junction. Throws Error on bad options.
TownMap generateTown(const TownOptions& options, uint64_t seed);

}  // namespace hdprior
