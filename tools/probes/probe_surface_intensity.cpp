// Does a lidar return's intensity tell the road from what lies beside it? Every STEP-th sweep, at
// the ground-truth pose: the intensity of ground points (segmentGround) inside the drivable area
// (more than 0.5 m in), and outside it (more than 0.5 m out), as quartiles per range band; then the
// same for the road points (extractRoadPoints) alone: those outside are where the walk spilled.
//   probe_surface_intensity LOG STEP
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "probe_arguments.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/road_points.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/hd_map.h"

using namespace hdprior;

namespace {

void printQuartiles(const char* what, std::vector<int> v) {
  if (v.empty()) {
    std::printf(" %s -", what);
    return;
  }
  std::sort(v.begin(), v.end());
  std::printf(" %s n %6zu q25 %3d q50 %3d q75 %3d q90 %3d |", what, v.size(), v[v.size() / 4], v[v.size() / 2],
              v[3 * v.size() / 4], v[9 * v.size() / 10]);
}

}  // namespace

int main(int argc, char** argv) try {
  const size_t step = probeStep(argc, argv, "probe_surface_intensity");
  if (step == 0) return 2;
  const ArgoverseLog log(argv[1]);
  const HdMap map = HdMap::load(log.mapFiles());
  const double bands[] = {0, 10, 20, 40};
  std::vector<int> inside[3], outside[3], roadInside[3], roadOutside[3];
  for (size_t s = 0; s < log.sweepTimestamps().size(); s += step) {
    const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
    const auto sweep = log.sweep(s);
    const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
    const std::vector<uint8_t> ground = segmentGround(points);
    const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*sweep), ground);
    for (size_t i = 0; i < points.size(); ++i) {
      if (!ground[i]) continue;
      const double range = points[i].head<2>().norm();
      const int band = range < bands[1] ? 0 : range < bands[2] ? 1 : range < bands[3] ? 2 : -1;
      if (band < 0) continue;
      const double d = map.boundaryDistance().distance((cityTEgo * points[i]).head<2>());
      if (d < -0.5) inside[band].push_back(sweep->points[i].intensity);
      if (d > 0.5) outside[band].push_back(sweep->points[i].intensity);
      if (road[i] && d < -0.5) roadInside[band].push_back(sweep->points[i].intensity);
      if (road[i] && d > 0.5) roadOutside[band].push_back(sweep->points[i].intensity);
    }
  }
  for (int b = 0; b < 3; ++b) {
    std::printf("range %2.0f-%2.0f m:", bands[b], bands[b + 1]);
    printQuartiles("inside", inside[b]);
    printQuartiles("outside", outside[b]);
    std::printf("\n              road points:");
    printQuartiles("inside", roadInside[b]);
    printQuartiles("outside", roadOutside[b]);
    std::printf("\n");
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
