// Is a road edge without a kerb (a flush verge) visible in the road's cross-section? The sweep's
// ground points within 8 m ahead or behind, at the ground-truth pose, binned by their lateral
// offset (0.25 m): the median height per bin (city z minus the ego's), beside the drivable area's
// edges straight left and right of the ego.
//   probe_cross_section LOG SWEEP
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/hd_map.h"

using namespace hdprior;

namespace {

constexpr double kBin = 0.25;
constexpr int kBins = 160;  // -20 .. 20 m

// Metres from the ego to the drivable area's edge along `direction` (0.05 m steps, at most 40 m).
double drivableEdge(const HdMap& map, const Eigen::Vector2d& from, const Eigen::Vector2d& direction) {
  double d = 0.0;
  while (d < 40.0 && map.drivable().contains(from + d * direction)) d += 0.05;
  return d;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: probe_cross_section LOG SWEEP\n");
    return 2;
  }
  const ArgoverseLog log(argv[1]);
  const size_t sweep = size_t(std::atol(argv[2]));
  const HdMap map = HdMap::load(log.mapFiles());
  const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps().at(sweep));
  const Eigen::Vector3d pose = planarPose(cityTEgo);
  const Eigen::Vector2d left(-std::sin(pose.z()), std::cos(pose.z()));
  std::printf("drivable edges: left %+.2f m, right %+.2f m\n", drivableEdge(map, pose.head<2>(), left),
              -drivableEdge(map, pose.head<2>(), -left));

  const std::vector<Eigen::Vector3d> points = sweepPoints(*log.sweep(sweep));
  const std::vector<uint8_t> ground = segmentGround(points);
  std::vector<std::vector<double>> bins(kBins);
  for (size_t i = 0; i < points.size(); ++i) {
    if (!ground[i] || std::abs(points[i].x()) > 8.0) continue;
    const int b = int(std::floor(points[i].y() / kBin)) + kBins / 2;
    if (b >= 0 && b < kBins) bins[size_t(b)].push_back((cityTEgo * points[i]).z() - cityTEgo.translation().z());
  }
  std::printf("lateral_m height_m points\n");
  for (int b = 0; b < kBins; ++b) {
    std::vector<double>& v = bins[size_t(b)];
    if (v.size() < 3) continue;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    std::printf("%+6.2f %7.3f %zu\n", (b - kBins / 2 + 0.5) * kBin, v[v.size() / 2], v.size());
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
