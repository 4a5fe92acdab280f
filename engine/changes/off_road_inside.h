#pragma once
#include <cstdint>
#include <vector>

#include "engine/changes/change_options.h"
#include "engine/changes/missing_surface.h"
#include "engine/changes/surface_evidence.h"
#include "engine/io/vector_map.h"

namespace hdprior {

class BoundaryDistance;
class GroundHeight;

// Ground inside a drivable area that is not road: a polygon drawn over a sidewalk or a verge.
struct OffRoadInside {
  int64_t areaId = 0;       // the polygon it lies in
  MissingSurface region;    // its outline, size, depth inside the boundary, frames and confidence
  double brightness = 0.0;  // its cells' median brightness over the log's road's (SurfaceCell::brightness)
};

// The regions of ground the road walk did not reach lying inside the drivable area
// (surfaceBeyondBoundary, inside) that are brighter than the log's road by
// options.offRoadBrightness (the walk also stops short of road it cannot see into, junction arms
// and cross streets, and that reads as asphalt) and reach the boundary's band (a raised island
// the map paints over lies inside, road all round it).
std::vector<OffRoadInside> findOffRoadInside(const SurfaceEvidence& evidence, const VectorMap& map, const BoundaryDistance& drivableDistance,
                                             const GroundHeight* groundHeight, const ChangeOptions& options);

}  // namespace hdprior
