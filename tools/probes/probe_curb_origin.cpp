// Where do the curb points lie? Every STEP-th sweep, at the ground-truth pose: the curb points
// (road points where the ring walk ended at a height step) by their signed distance to the drivable
// boundary (inside by more than 0.5 m, within 0.5 m, outside by more), and how many of each have
// an object (a non-ground return 0.15-1.5 m above them within 0.4 m) standing by: a parked car's
// side rather than a kerb.
//   probe_curb_origin LOG STEP
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

struct Counts {
  size_t inside = 0, insideByObject = 0, edge = 0, edgeByObject = 0, outside = 0, outsideByObject = 0;
  void add(double distance, bool byObject) {
    size_t& n = distance < -0.5 ? inside : (distance <= 0.5 ? edge : outside);
    size_t& o = distance < -0.5 ? insideByObject : (distance <= 0.5 ? edgeByObject : outsideByObject);
    ++n;
    o += byObject;
  }
  void print(const char* what) const {
    std::printf("%s curbs: inside > 0.5 m %zu (%zu by an object), at the edge %zu (%zu), outside %zu (%zu)\n", what, inside,
                insideByObject, edge, edgeByObject, outside, outsideByObject);
  }
};

bool objectStandsBy(const std::vector<Eigen::Vector3d>& points, const std::vector<uint8_t>& ground, const Eigen::Vector3d& p) {
  for (size_t j = 0; j < points.size(); ++j) {
    if (!ground[j] && points[j].z() > p.z() + 0.15 && points[j].z() < p.z() + 1.5 &&
        (points[j].head<2>() - p.head<2>()).squaredNorm() < 0.16) {
      return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) try {
  const size_t step = probeStep(argc, argv, "probe_curb_origin");
  if (step == 0) return 2;
  const ArgoverseLog log(argv[1]);
  const HdMap map = HdMap::load(log.mapFiles());
  Counts all;
  for (size_t s = 0; s < log.sweepTimestamps().size(); s += step) {
    const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
    const auto sweep = log.sweep(s);
    const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
    const std::vector<uint8_t> ground = segmentGround(points);
    const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*sweep), ground);
    Counts counts;
    for (size_t i = 0; i < points.size(); ++i) {
      if (road[i] != kCurbPoint) continue;
      const double distance = map.boundaryDistance().distance((cityTEgo * points[i]).head<2>());
      const bool byObject = objectStandsBy(points, ground, points[i]);
      counts.add(distance, byObject);
      all.add(distance, byObject);
    }
    std::printf("sweep %3zu ", s);
    counts.print("");
  }
  all.print("all");
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
