#include "engine/changes/off_road_inside.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "engine/geom/polygon2d.h"

namespace hdprior {

namespace {

double median(std::vector<float> v) {
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The median brightness of the cells (of `indices`, or of every road cell) with ground points.
double medianBrightness(const SurfaceEvidence& evidence, const std::vector<int>* indices) {
  std::vector<float> values;
  const auto take = [&](size_t i) {
    if (evidence.cells()[i].groundPoints > 0) values.push_back(evidence.cells()[i].brightness());
  };
  if (indices)
    for (int i : *indices) take(size_t(i));
  else
    for (size_t i = 0; i < evidence.cells().size(); ++i)
      if (evidence.surface(i) == Surface::Road) take(i);
  return median(std::move(values));
}

int64_t areaAt(const VectorMap& map, const Eigen::Vector2d& p) {
  for (const DrivableArea& a : map.drivableAreas)
    if (ringContains(ringOf(a.areaBoundary), p)) return a.id;
  return 0;
}

}  // namespace

std::vector<OffRoadInside> findOffRoadInside(const SurfaceEvidence& evidence, const VectorMap& map, const BoundaryDistance& drivableDistance,
                                             const GroundHeight* groundHeight, const ChangeOptions& options) {
  const double road = medianBrightness(evidence, nullptr);
  std::vector<OffRoadInside> out;
  if (!(road > 0.0)) return out;
  for (SurfaceRegion& r : surfaceBeyondBoundary(evidence, drivableDistance, groundHeight, Surface::NotRoad, -1.0, options)) {
    const double brightness = medianBrightness(evidence, &r.cells) / road;
    if (std::getenv("HDPRIOR_OFFROAD_DUMP")) {
      std::fprintf(stderr, "OFFROAD area %.1f depth %.2f bright %.2f road %.2f shallow %.2f best %d at", r.surface.area, r.surface.depth, brightness, road, r.shallowest, r.surface.bestFrame);
      for (const auto& p : r.surface.outline) std::fprintf(stderr, " %.2f,%.2f", p.x(), p.y());
      std::fprintf(stderr, "\n");
    }
    // A verge the polygon was drawn over runs on out of it; a raised island the map paints over
    // lies inside, road all round it.
    const bool bordersTheBoundary = r.shallowest <= options.missingGap + evidence.geometry().resolution;
    if (!(brightness >= options.offRoadBrightness) || !bordersTheBoundary) continue;
    out.push_back({areaAt(map, r.deepest), std::move(r.surface), brightness});
  }
  return out;
}

}  // namespace hdprior
