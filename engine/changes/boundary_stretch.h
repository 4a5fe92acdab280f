#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/changes/map_verdict.h"
#include "engine/changes/surface_evidence.h"
#include "engine/io/vector_map.h"

namespace hdprior {

class BoundaryDistance;

// A stretch of a drivable area's boundary (ChangeOptions::stretchLength) and what the lidar says of it.
struct BoundaryStretch {
  int64_t areaId = 0;
  int index = 0;                      // along the polygon's boundary from its first vertex
  std::vector<Eigen::Vector2d> line;  // city frame
  MapVerdict verdict = MapVerdict::Unobserved;
  double confidence = 0.0;  // 0..1: how sure the verdict is, from the share and the number of samples agreeing
  int samples = 0, observed = 0, contradicted = 0, open = 0;  // boundary samples, ChangeOptions::sampleSpacing apart
  // The evidence: where the lidar's road edge lies, metres outwards of the map's boundary
  // (median over the contradicting samples, else over the observed ones), and what it is.
  double offset = 0.0;
  std::string evidence;  // "kerb_offset" (consistent), "road_beyond_boundary", "road_across_gap", "kerb_inside", "polygon_offset", "road_continues" or ""
  Eigen::Vector2d polygonShift = Eigen::Vector2d::Constant(NAN);  // "polygon_offset": the polygon's translation onto the edges seen
  int curbPoints = 0;
  double groundOffset = 0.0;  // lidar ground minus the ground-height raster, mean, metres (NaN: none)
  int firstFrame = -1, bestFrame = -1;
  double nearestView = 1e9;  // metres: the nearest the lidar came to the edges the verdict rests on

  // Unobserved though samples contradict the map: too few of them to say either way.
  bool undecided() const { return verdict == MapVerdict::Unobserved && contradicted > 0 && !evidence.empty() && evidence != "road_continues"; }
};

// The verdicts of the polygons' boundary stretches, polygon by polygon. Samples that lie inside
// another polygon (seams between polygons: no kerb is there to see) are left out; a stretch made
// of them only is not returned. A stretch not contradicted on its own is where its polygon is
// offset as a whole (PolygonOffset) and its edges lie where the offset puts them.
std::vector<BoundaryStretch> checkBoundaries(const std::vector<DrivableArea>& areas, const SurfaceEvidence& evidence,
                                             const BoundaryDistance& drivableDistance, const ChangeOptions& options);

}  // namespace hdprior
