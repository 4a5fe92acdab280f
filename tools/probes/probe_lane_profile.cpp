// The mean intensity across the map's painted lane lines: for every sweep, the ground returns
// within RANGE metres of the lidar (default 8) and 2 m of a painted lane boundary, each as its
// intensity over the median of its ring's ground returns, averaged per line in 0.125 m bins of
// their offset to it (left positive). Prints one row per line with at least 200 returns: the line,
// its mark, the returns, and the bins' means from -1.5 to +1.5 m.
//   probe_lane_profile LOG [RANGE]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "engine/error.h"
#include "engine/geom/polygon2d.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/hd_map.h"

using namespace hdprior;
using Vec2 = Eigen::Vector2d;

namespace {

constexpr double kReach = 1.5, kBin = 0.125;
constexpr int kBins = int(2 * kReach / kBin);

struct Line {
  long long lane = 0;
  std::string side, mark;
  std::vector<Vec2> points;
  std::array<double, kBins> sum{};
  std::array<int, kBins> count{};
};

int median(std::vector<int> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::fprintf(stderr, "usage: probe_lane_profile LOG [RANGE]\n");
    return 2;
  }
  const ArgoverseLog log(argv[1]);
  const double range = argc > 2 ? std::atof(argv[2]) : 8.0;
  const HdMap map = HdMap::load(log.mapFiles());
  std::vector<Line> lines;
  std::set<LaneLineKey> seen;
  for (const LaneSegment& lane : map.vectorMap().laneSegments)
    for (const auto& [line, type, side] : {std::tuple{&lane.leftLaneBoundary, &lane.leftLaneMarkType, "left"},
                                           std::tuple{&lane.rightLaneBoundary, &lane.rightLaneMarkType, "right"}}) {
      if (line->size() < 2 || !isPaintedMark(*type) || !seen.insert(laneLineKey(*line)).second) continue;
      Line l{lane.id, side, *type, {}, {}, {}};
      for (const auto& p : *line) l.points.push_back(p.head<2>());
      lines.push_back(std::move(l));
    }
  for (size_t s = 0; s < log.sweepTimestamps().size(); ++s) {
    const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
    const auto sweep = log.sweep(s);
    const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
    const std::vector<uint8_t> ground = segmentGround(points);
    std::map<int, std::vector<int>> rings;
    for (size_t i = 0; i < points.size(); ++i)
      if (ground[i] && points[i].head<2>().norm() <= range) rings[sweep->points[i].laserNumber].push_back(sweep->points[i].intensity);
    std::map<int, int> ringMedian;
    for (auto& [ring, values] : rings) ringMedian[ring] = std::max(1, median(values));
    for (size_t i = 0; i < points.size(); ++i) {
      if (!ground[i] || points[i].head<2>().norm() > range) continue;
      const Vec2 city = (cityTEgo * points[i]).head<2>();
      Line* best = nullptr;
      double bestOffset = kReach;
      for (Line& l : lines) {
        const std::optional<double> o = leftOffset(l.points, city);
        if (o && std::abs(*o) < std::abs(bestOffset)) best = &l, bestOffset = *o;
      }
      if (!best) continue;
      const int b = std::clamp(int(std::floor((bestOffset + kReach) / kBin)), 0, kBins - 1);
      best->sum[b] += double(sweep->points[i].intensity) / ringMedian[sweep->points[i].laserNumber];
      ++best->count[b];
    }
  }
  for (const Line& l : lines) {
    int n = 0;
    for (int c : l.count) n += c;
    if (n < 200) continue;
    std::printf("%lld %-5s %-22s %6d |", l.lane, l.side.c_str(), l.mark.c_str(), n);
    for (int b = 0; b < kBins; ++b) std::printf(" %4.2f", l.count[b] ? l.sum[b] / l.count[b] : 0.0);
    std::printf("\n");
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
