#pragma once
#include <vector>

#include "engine/geom/polygon2d.h"
#include "engine/io/vector_map.h"

namespace hdprior {

// Where a crossing could be painted that the world does not have: across a street 6-9 m from
// where it leaves a junction (a lane whose predecessor or successor is an intersection lane),
// kerb to kerb of the world's drivable area, shaped like the towns' crossings (edges across the
// street, 3 m apart), clear of the world's crossings and of each other. Ids are 0.
std::vector<PedestrianCrossing> crosswalkSites(const VectorMap& world);

}  // namespace hdprior
