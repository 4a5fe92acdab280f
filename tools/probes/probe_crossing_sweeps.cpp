// How bright a crossing's paint is against the asphalt of the ring that sees it, sweep by sweep. A
// simulated log only (the paint is drawn again from the log's map, at the ground-truth pose). For
// each sweep whose pose is within 20 m of crossing ID: the ground returns within 12 m of the lidar
// that fall inside the crossing, their mean range and bearing, the sweep's median intensity, and
// for the returns on a stripe: their mean intensity, the mean median of their rings, and the share
// brighter than 1.7x their ring's median (the paint reading's test) and than 1.7x the larger of the
// sweep's and the ring's median (the test before 2026-12-07).
//   probe_crossing_sweeps LOG ID
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/hd_map.h"
#include "engine/sim/road_paint.h"
#include "crossing_frame.h"

using namespace hdprior;

namespace {

constexpr double kRange = 12.0, kContrast = 1.7;

int median(std::vector<int> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void probeSweep(const ArgoverseLog& log, size_t s, const SE3& cityTEgo, const CrossingFrame& box, const RoadPaint& paint) {
  const auto sweep = log.sweep(s);
  const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
  const std::vector<uint8_t> ground = segmentGround(points);
  std::vector<int> near;
  std::map<int, std::vector<int>> rings;
  for (size_t i = 0; i < points.size(); ++i)
    if (ground[i] && points[i].head<2>().norm() <= kRange) {
      near.push_back(sweep->points[i].intensity);
      rings[sweep->points[i].laserNumber].push_back(sweep->points[i].intensity);
    }
  if (near.empty()) return;
  const int sweepMedian = median(near);
  std::map<int, int> ringMedian;
  for (auto& [ring, values] : rings) ringMedian[ring] = median(values);
  int inside = 0, onStripe = 0, brightRing = 0, brightBefore = 0;
  double range = 0, bearing = 0, stripeSum = 0, ringSum = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!ground[i] || points[i].head<2>().norm() > kRange) continue;
    const Eigen::Vector2d city = (cityTEgo * points[i]).head<2>();
    if (!box.contains(city)) continue;
    ++inside;
    range += points[i].head<2>().norm();
    bearing += std::atan2(points[i].y(), points[i].x()) * 180.0 / M_PI;
    if (paint.reflectivityAt(city) == 0) continue;
    const int value = sweep->points[i].intensity, rm = ringMedian[sweep->points[i].laserNumber];
    ++onStripe;
    stripeSum += value;
    ringSum += rm;
    brightRing += value > kContrast * rm;
    brightBefore += value > kContrast * std::max(rm, sweepMedian);
  }
  if (onStripe == 0) return;
  std::printf("frame %3zu: %4d returns inside, range %5.1f m, bearing %6.1f deg, sweep median %3d; on a stripe %4d: mean %5.1f, "
              "ring median %5.1f, bright against the ring %.2f, against the larger median %.2f\n",
              s, inside, range / inside, bearing / inside, sweepMedian, onStripe, stripeSum / onStripe, ringSum / onStripe,
              double(brightRing) / onStripe, double(brightBefore) / onStripe);
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: probe_crossing_sweeps LOG ID\n");
    return 2;
  }
  const ArgoverseLog log(argv[1]);
  const long long id = std::atoll(argv[2]);
  const HdMap map = HdMap::load(log.mapFiles());
  for (const PedestrianCrossing& c : map.vectorMap().pedestrianCrossings) {
    if (c.id != id || c.edge1.size() < 2 || c.edge2.size() < 2) continue;
    const CrossingFrame box = frameOf(c);
    const RoadPaint paint(map.vectorMap(), box.centre - Eigen::Vector2d(50, 50), box.centre + Eigen::Vector2d(50, 50));
    std::printf("crossing %lld: %.1f m long, %.2f m wide\n", id, 2 * box.halfLength, 2 * box.halfWidth);
    for (size_t s = 0; s < log.sweepTimestamps().size(); ++s) {
      const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
      if ((cityTEgo.translation().head<2>() - box.centre).norm() <= 20 + box.halfLength) probeSweep(log, s, cityTEgo, box, paint);
    }
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
