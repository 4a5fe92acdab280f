// Does a cell's mean brightness tell the ground the road walk did not reach on the road from that
// beside it? Every STEP-th sweep at the log's poses (city_SE3_egovehicle): each ground point's
// intensity over its ring's lower quartile of road points (SweepPaint's brightness, at every
// range), averaged in 0.5 m city cells; then the quantiles of the cell means (cells of 3 points or
// more), inside the drivable area (1 m in) and outside it (1 m out), split by the walk's label.
//   probe_cell_brightness LOG STEP
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>
#include <vector>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "probe_arguments.h"

using namespace hdprior;

namespace {

struct Cell {
  double sum = 0;
  int n = 0, road = 0;
  float nearest = 1e9f;
};

double quartile(std::vector<uint8_t> v) {
  if (v.empty()) return 1.0;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 4), v.end());
  return std::max(1.0, double(v[v.size() / 4]));
}

void print(const char* what, std::vector<double> v) {
  std::sort(v.begin(), v.end());
  if (v.empty()) return void(std::printf("  %-34s -\n", what));
  auto q = [&](double s) { return v[size_t(s * double(v.size() - 1))]; };
  size_t above = size_t(std::count_if(v.begin(), v.end(), [](double x) { return x >= 1.6; }));
  std::printf("  %-34s n %6zu q10 %.2f q25 %.2f q50 %.2f q75 %.2f q90 %.2f  >=1.6: %.0f %%\n", what, v.size(), q(0.1), q(0.25), q(0.5),
              q(0.75), q(0.9), 100.0 * double(above) / double(v.size()));
}

}  // namespace

int main(int argc, char** argv) try {
  const size_t step = probeStep(argc, argv, "probe_cell_brightness");
  if (step == 0) return 2;
  const ArgoverseLog log(argv[1]);
  const HdMap map = HdMap::load(log.mapFiles());
  const double size = 0.5;
  std::unordered_map<int64_t, Cell> cells;
  auto key = [&](const Eigen::Vector2d& p) { return (int64_t(std::floor(p.x() / size)) << 32) ^ (int64_t(std::floor(p.y() / size)) & 0xffffffff); };
  std::unordered_map<int64_t, Eigen::Vector2d> centres;
  for (size_t s = 0; s < log.sweepTimestamps().size(); s += step) {
    const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[s]);
    const auto sweep = log.sweep(s);
    const LabelledSweep labelled = labelSweep(*sweep, levelRotation(cityTEgo));
    std::map<uint8_t, std::vector<uint8_t>> ringRoad;
    std::vector<uint8_t> all;
    for (size_t i = 0; i < labelled.points.size(); ++i)
      if (labelled.road[i]) ringRoad[sweep->points[i].laserNumber].push_back(sweep->points[i].intensity), all.push_back(sweep->points[i].intensity);
    const double sweepQuartile = quartile(all);
    std::map<uint8_t, double> asphalt;
    for (auto& [laser, v] : ringRoad) asphalt[laser] = v.size() >= 50 ? quartile(v) : sweepQuartile;
    const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
    for (size_t i = 0; i < labelled.points.size(); ++i) {
      if (!labelled.ground[i]) continue;
      const auto a = asphalt.find(sweep->points[i].laserNumber);
      const double norm = a == asphalt.end() ? sweepQuartile : a->second;
      const Eigen::Vector2d city = r * labelled.points[i].head<2>() + cityTEgo.translation().head<2>();
      Cell& c = cells[key(city)];
      centres[key(city)] = city;
      c.sum += sweep->points[i].intensity / norm;
      ++c.n;
      c.road += labelled.road[i] != 0;
      c.nearest = std::min(c.nearest, float(labelled.points[i].head<2>().norm()));
    }
  }
  for (double lo : {0.0, 15.0}) {
    std::vector<double> v[2][2];  // [outside][road]
    for (const auto& [k, c] : cells) {
      if (c.n < 3 || c.nearest < lo || c.nearest >= lo + 15.0) continue;
      const double d = map.boundaryDistance().distance(centres[k]);
      if (!std::isfinite(d) || std::abs(d) < 1.0) continue;
      const bool road = 2 * c.road >= c.n;
      v[d > 0][road].push_back(c.sum / c.n);
    }
    std::printf("cells seen from %.0f-%.0f m:\n", lo, lo + 15.0);
    print("inside, road (walk reached)", v[0][1]);
    print("inside, not road (walk did not)", v[0][0]);
    print("outside, road (spill)", v[1][1]);
    print("outside, not road", v[1][0]);
  }
  return 0;
} catch (const Error& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 2;
}
