#pragma once
#include <Eigen/Core>

#include "engine/changes/boundary_samples.h"
#include "engine/changes/change_options.h"
#include "engine/changes/surface_evidence.h"

namespace hdprior {

// Where the lidar puts the road's edge across one boundary sample of the map.
struct BoundaryReading {
  enum class Kind {
    Unobserved,  // too little seen on one side to place an edge
    Edge,        // the road ends at `offset` metres outwards of the map's boundary (negative: inwards)
    Open,        // the road goes on beyond the reach outwards: surface the map lacks
    AcrossGap,   // the road goes on across a gap in the map, `offset` metres wide, to another drivable area
  };
  Kind kind = Kind::Unobserved;
  double offset = 0.0;       // metres along the outward normal (Edge; the gap's width for AcrossGap; the reach for Open)
  int curbPoints = 0;        // kerb points the walks ended at, near the edge
  float groundOffset = NAN;  // mean lidar ground minus ground-height raster along the profile, metres
  int firstFrame = -1, bestFrame = -1;
  float nearestView = 1e9f;  // metres: the nearest the lidar came to the road's edge here
};

// Reads the road's edge along the sample's normal in the evidence: walking outwards over road
// cells from the road nearest inside the boundary to where road ends and is followed by ground
// that is not road or by a kerb; or, with ground that is not road just inside, inwards to a kerb
// where road begins.
BoundaryReading readBoundary(const SurfaceEvidence& evidence, const BoundarySample& sample, const ChangeOptions& options);

}  // namespace hdprior
