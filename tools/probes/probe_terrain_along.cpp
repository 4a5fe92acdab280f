// Does the ground-height raster see the along-track position? Every STEP-th sweep, at the
// ground-truth pose: the road points placed in the city frame, thinned to one per 0.5 m cell, and
// for along-track offsets d in [-4, 4] m the misfit of their heights to the raster at the shifted
// places, with a height offset (and, second column, a pitch) fitted out. Prints the best d, the
// misfit's rise 1 m away (in the points' own residual variance) and the raster's relief there.
//   probe_terrain_along LOG STEP
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include <Eigen/Dense>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "probe_arguments.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/road_points.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/ground_height.h"
#include "engine/map/hd_map.h"

using namespace hdprior;

namespace {

struct Sample {
  Eigen::Vector2d xy;
  double z = 0, along = 0;
};

// Residual sum of squares of z - h(xy + d a) after fitting c (+ p along).
double misfit(const std::vector<Sample>& samples, const GroundHeight& ground, const Eigen::Vector2d& a, double d,
              bool pitch, double* rms) {
  Eigen::MatrixXd A(samples.size(), pitch ? 2 : 1);
  Eigen::VectorXd b(samples.size());
  int n = 0;
  for (const Sample& s : samples) {
    const double h = ground.bilinearAt(s.xy + d * a);
    if (!std::isfinite(h)) continue;
    A(n, 0) = 1.0;
    if (pitch) A(n, 1) = s.along;
    b(n) = s.z - h;
    ++n;
  }
  if (n < 20) return NAN;
  const Eigen::MatrixXd An = A.topRows(n);
  const Eigen::VectorXd bn = b.head(n);
  const Eigen::VectorXd x = An.colPivHouseholderQr().solve(bn);
  const double ssr = (An * x - bn).squaredNorm();
  if (rms) *rms = std::sqrt(ssr / n);
  return ssr / n;
}

}  // namespace

int main(int argc, char** argv) try {
  const size_t step = probeStep(argc, argv, "probe_terrain_along");
  if (step == 0) return 2;
  const ArgoverseLog log(argv[1]);
  const HdMap map = HdMap::load(log.mapFiles());
  const GroundHeight& ground = map.groundHeight();
  for (size_t s = 0; s < log.sweepTimestamps().size(); s += step) {
    const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
    const auto sweep = log.sweep(s);
    const std::vector<Eigen::Vector3d> points = sweepPoints(*sweep);
    const std::vector<uint8_t> groundFlags = segmentGround(points);
    const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*sweep), groundFlags);
    const Eigen::Vector2d a = cityTEgo.linear().col(0).head<2>().normalized();
    std::map<std::pair<int, int>, Sample> cells;
    for (size_t i = 0; i < points.size(); ++i) {
      if (!road[i]) continue;
      const Eigen::Vector3d p = cityTEgo * points[i];
      const std::pair<int, int> key(int(std::floor(points[i].x() / 0.5)), int(std::floor(points[i].y() / 0.5)));
      if (cells.count(key)) continue;
      cells[key] = Sample{p.head<2>(), p.z(), points[i].x()};
    }
    std::vector<Sample> samples;
    double minAlong = 1e9, maxAlong = -1e9;
    for (const auto& [k, v] : cells) {
      samples.push_back(v);
      minAlong = std::min(minAlong, v.along);
      maxAlong = std::max(maxAlong, v.along);
    }
    std::printf("sweep %3zu n %4zu along [%5.1f, %5.1f]", s, samples.size(), minAlong, maxAlong);
    for (bool pitch : {false, true}) {
      double best = 1e18, bestD = 0, rms0 = 0;
      std::vector<double> curve;
      for (int k = -40; k <= 40; ++k) {
        double rms = 0;
        const double m = misfit(samples, ground, a, 0.1 * k, pitch, &rms);
        curve.push_back(m);
        if (k == 0) rms0 = rms;
        if (m < best) best = m, bestD = 0.1 * k;
      }
      const int ib = int(std::lround(bestD / 0.1)) + 40;
      const double rise = 0.5 * ((ib >= 10 ? curve[ib - 10] : NAN) + (ib + 10 <= 80 ? curve[ib + 10] : NAN)) - best;
      std::printf(" | %s best d %5.2f rms %.3f rise1m/var %6.2f", pitch ? "c+p" : "c  ", bestD, rms0, rise / (best + 1e-9));
    }
    // Raster relief along the heading: height difference over +-20 m minus the straight line.
    const Eigen::Vector2d o = cityTEgo.translation().head<2>();
    const double h0 = ground.bilinearAt(o), hp = ground.bilinearAt(o + 20 * a), hm = ground.bilinearAt(o - 20 * a);
    std::printf(" | grade %+.3f curv(20m) %+.3f\n", (hp - hm) / 40.0, 0.5 * (hp + hm) - h0);
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
