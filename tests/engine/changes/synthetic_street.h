// A street seen by the lidar, made up point by point: a road surface between kerbs at y = ±5 m
// (or wherever the world function puts it) and raised sidewalks beyond, as one labelled sweep
// with its ego at the city origin.
#pragma once
#include <functional>

#include "engine/changes/surface_evidence.h"
#include "engine/io/vector_map.h"
#include "engine/lidar/road_points.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/map/synthetic_maps.h"

namespace hdprior::test {

struct GroundPoint {
  bool road = false;    // the world's road surface
  bool walked = false;  // reached by the road walk
  bool kerb = false;    // where the walk ended at a kerb
};

// Points every 0.1 m over [-20, 20] x [-20, 20]; `world` says what lies at (x, y).
inline SurfaceEvidence streetEvidence(const std::function<GroundPoint(double, double)>& world) {
  LabelledSweep sweep;
  for (double x = -19.95; x < 20; x += 0.1)
    for (double y = -19.95; y < 20; y += 0.1) {
      const GroundPoint g = world(x, y);
      const double z = g.road ? 0.0 : 0.15;
      sweep.points.emplace_back(x, y, z);
      sweep.ground.push_back(1);
      sweep.road.push_back(g.kerb ? kCurbPoint : g.walked ? kRoadPoint : 0);
    }
  GridGeometry grid;
  grid.origin = {-25, -25};
  grid.resolution = 0.5;
  grid.cols = grid.rows = 100;
  SurfaceEvidence evidence(grid);
  evidence.add(0, sweep, SE3::Identity(), nullptr);
  return evidence;
}

// The HD map of these polygons (ids 1, 2, ...).
inline HdMap streetMap(std::initializer_list<Polyline3> polygons) {
  HdMapOptions o;
  o.ndtCellSizes = {1.0};
  return HdMap::build(mapOf(polygons), std::nullopt, o, "synthetic");
}

// The straight street: road for |y| < 5, walked up to the kerbs.
inline GroundPoint straightStreet(double, double y) {
  const double a = std::abs(y);
  return {a < 5.0, a < 5.0, a > 4.8 && a < 5.0};
}

}  // namespace hdprior::test
