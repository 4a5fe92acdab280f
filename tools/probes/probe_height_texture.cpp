// Does the ground-height raster's texture observe the position along the road? The sweep's ground
// points inside the drivable area, placed with the ground-truth pose and then shifted along and
// across the heading, against the raster: the RMS of their height residuals (median removed, as
// the altitude is free; each clipped at 0.1 m). A minimum at (0, 0) sharper than the noise would be
// along-track evidence on straight roads.
//   probe_height_texture LOG [SWEEP=0] [MAX_RANGE_M=40]
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

std::vector<Eigen::Vector3d> groundRoadPoints(const ArgoverseLog& log, const HdMap& map, size_t sweep, double maxRange) {
  const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps().at(sweep));
  const std::vector<Eigen::Vector3d> points = sweepPoints(*log.sweep(sweep));
  const std::vector<uint8_t> ground = segmentGround(points);
  std::vector<Eigen::Vector3d> out;
  for (size_t i = 0; i < points.size(); ++i) {
    const double range = points[i].head<2>().norm();
    if (!ground[i] || range > maxRange || range < 3.0) continue;
    const Eigen::Vector3d city = cityTEgo * points[i];
    if (map.drivable().contains(city.head<2>())) out.push_back(city);
  }
  return out;
}

double residualRms(const std::vector<Eigen::Vector3d>& points, const GroundHeight& ground, const Eigen::Vector2d& shift) {
  std::vector<double> r;
  for (const Eigen::Vector3d& p : points) {
    const double h = ground.bilinearAt(p.head<2>() + shift);
    if (std::isfinite(h)) r.push_back(p.z() - h);
  }
  if (r.empty()) return NAN;
  std::vector<double> sorted = r;
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  double sum = 0.0;
  for (double x : r) sum += std::min((x - median) * (x - median), 0.01);
  return std::sqrt(sum / double(r.size()));
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::fprintf(stderr, "usage: probe_height_texture LOG [SWEEP] [MAX_RANGE_M]\n");
    return 2;
  }
  const ArgoverseLog log(argv[1]);
  const size_t sweep = argc > 2 ? size_t(std::atol(argv[2])) : 0;
  const double maxRange = argc > 3 ? std::atof(argv[3]) : 40.0;
  const HdMap map = HdMap::load(log.mapFiles());
  const std::vector<Eigen::Vector3d> points = groundRoadPoints(log, map, sweep, maxRange);
  const double yaw = planarPose(log.cityTEgo().at(log.sweepTimestamps().at(sweep))).z();
  const Eigen::Vector2d along(std::cos(yaw), std::sin(yaw)), lateral(-std::sin(yaw), std::cos(yaw));
  std::printf("%zu ground points in the drivable area; rows: lateral shift (m), columns: along shift -4..4 m\n", points.size());
  for (double dl = -0.6; dl <= 0.61; dl += 0.3) {
    std::printf("%+.1f:", dl);
    for (double ds = -4.0; ds <= 4.001; ds += 0.5) std::printf(" %.4f", residualRms(points, map.groundHeight(), ds * along + dl * lateral));
    std::printf("\n");
  }
  std::printf("along -1..1 m by 0.1 m, no lateral shift:");
  for (double ds = -1.0; ds <= 1.001; ds += 0.1) std::printf(" %.4f", residualRms(points, map.groundHeight(), ds * along));
  std::printf("\n");
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
