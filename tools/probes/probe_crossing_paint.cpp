// Do painted pedestrian crossings show in the lidar intensity where the map puts them? Every
// STEP-th sweep, at the ground-truth pose: the ground points (segmentGround) within 25 m of a mapped
// crossing's centre line, binned by their distance across the crossing (from its centre line, in
// the direction a car drives over it), with the median intensity and the share above 30 per bin.
// A crossing the car drives over has its edges where the share jumps.
//   probe_crossing_paint LOG STEP
#include <algorithm>
#include <array>
#include <string>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/hd_map.h"
#include "crossing_frame.h"
#include "probe_arguments.h"

using namespace hdprior;

namespace {

constexpr double kBin = 0.25;
constexpr int kBins = 40;  // -5 .. 5 m across
const int kBright = std::getenv("BRIGHT") ? std::atoi(std::getenv("BRIGHT")) : 30;

}  // namespace

int main(int argc, char** argv) try {
  const size_t step = probeStep(argc, argv, "probe_crossing_paint");
  if (step == 0) return 2;
  const ArgoverseLog log(argv[1]);
  const HdMap map = HdMap::load(log.mapFiles());
  for (const PedestrianCrossing& c : map.vectorMap().pedestrianCrossings) {
    const CrossingFrame f = frameOf(c);
    std::array<std::vector<int>, kBins> bins;
    for (size_t s = 0; s < log.sweepTimestamps().size(); s += step) {
      const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
      if ((cityTEgo.translation().head<2>() - f.centre).norm() > 25 + f.halfLength) continue;
      const auto sweep = log.sweep(s);
      const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
      const std::vector<uint8_t> ground = segmentGround(points);
      for (size_t i = 0; i < points.size(); ++i) {
        if (!ground[i] || points[i].head<2>().norm() > 25) continue;
        const Eigen::Vector2d d = (cityTEgo * points[i]).head<2>() - f.centre;
        if (std::abs(d.dot(f.axis)) > f.halfLength - 1.0) continue;
        if (map.boundaryDistance().distance(f.centre + d) > -0.3) continue;
        const int b = static_cast<int>(std::floor(d.dot(f.across) / kBin)) + kBins / 2;
        if (b >= 0 && b < kBins) bins[b].push_back(sweep->points[i].intensity);
      }
    }
    size_t total = 0;
    for (const auto& b : bins) total += b.size();
    if (total == 0) continue;
    std::printf("crossing %lld: length %.1f m, mapped width %.2f m (edges at +-%.2f), %zu points\n",
                static_cast<long long>(c.id), 2 * f.halfLength, 2 * f.halfWidth, f.halfWidth, total);
    for (int b = 0; b < kBins; ++b) {
      std::vector<int>& v = bins[b];
      std::sort(v.begin(), v.end());
      const double bright = v.empty() ? 0 : double(std::count_if(v.begin(), v.end(), [](int x) { return x > kBright; })) / v.size();
      std::printf("  across %+5.2f m: n %5zu median %3d bright %4.2f %s\n", (b - kBins / 2 + 0.5) * kBin, v.size(),
                  v.empty() ? -1 : v[v.size() / 2], bright, std::string(static_cast<size_t>(bright * 40), '#').c_str());
    }
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
