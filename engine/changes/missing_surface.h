#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/changes/surface_evidence.h"

namespace hdprior {

class BoundaryDistance;
class GroundHeight;

// Road the lidar drove beside or on where the map has no drivable area.
struct MissingSurface {
  std::vector<Eigen::Vector2d> outline;  // closed polygon, city frame, counter-clockwise (first vertex not repeated)
  double area = 0.0;    // square metres of road cells
  double depth = 0.0;   // metres: how far it reaches outside the drivable area
  double confidence = 0.0;
  int roadPoints = 0;
  int firstFrame = -1, bestFrame = -1;
};

// The connected road cells (4-neighbours) lying more than options.missingGap outside every
// polygon, reaching options.missingMinDepth out and covering options.missingMinArea. Cells
// outside the ground-height raster's region of interest (where it has a height) are left out:
// the map was not drawn there.
std::vector<MissingSurface> findMissingSurfaces(const SurfaceEvidence& evidence, const BoundaryDistance& drivableDistance,
                                                const GroundHeight* groundHeight, const ChangeOptions& options);

// The outer outline of a set of grid cells (one 4-connected component), along the cell edges,
// counter-clockwise, collinear vertices dropped.
std::vector<Eigen::Vector2d> cellOutline(const GridGeometry& geometry, const std::vector<int>& cellIndices);

}  // namespace hdprior
