// Do the kerbs a keyframe sees fix its place along the road? Runs LOG through the pipeline (config C),
// then for every keyframe whose match is not rejected, moves the pose along the true heading by d in
// [-4, 4] m (0.05 m steps) from the ground truth and from the match's estimate, and counts the curb
// points within 0.2 m of the drivable boundary. Prints per keyframe: the curb count, how many of the
// curbs on the boundary at the truth lie on a boundary across the heading (gradient within 45 deg of
// it: a crossing street's kerb), the argmax of the count from the truth (0 is right) and from the
// estimate (the match's along error is right), the count's drop 1 m from its peak, and the match's
// along error.
//   probe_along_curbs LOG CONFIG
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>
#include <cstdio>
#include <vector>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/boundary_distance.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/prior_stage.h"

using namespace hdprior;

namespace {

constexpr double kBand = 0.2;

Eigen::Vector2d place(const Eigen::Vector3d& pose, const Eigen::Vector2d& p) {
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  return {c * p.x() - s * p.y() + pose.x(), s * p.x() + c * p.y() + pose.y()};
}

int onBoundary(const BoundaryDistance& b, const std::vector<Eigen::Vector2d>& curbs, const Eigen::Vector3d& pose) {
  int n = 0;
  for (const Eigen::Vector2d& p : curbs) {
    const double d = b.distance(place(pose, p));
    if (std::isfinite(d) && std::abs(d) <= kBand) ++n;
  }
  return n;
}

struct Profile {
  double argmax = 0;
  int peak = 0, drop = 0;  // drop: peak minus the larger count 1 m either side
};

// The count along the heading of `truthYaw` through `from`; ties go to the offset nearest 0.
Profile profile(const BoundaryDistance& b, const std::vector<Eigen::Vector2d>& curbs, const Eigen::Vector3d& from, double truthYaw) {
  const Eigen::Vector2d a(std::cos(truthYaw), std::sin(truthYaw));
  std::vector<int> counts;
  for (int i = -80; i <= 80; ++i) {
    Eigen::Vector3d pose = from;
    pose.head<2>() += 0.05 * i * a;
    counts.push_back(onBoundary(b, curbs, pose));
  }
  Profile p;
  int best = -1;
  for (int i = 0; i < int(counts.size()); ++i) {
    const int off = std::abs(i - 80);
    if (counts[i] > p.peak || (counts[i] == p.peak && off < std::abs(best - 80))) {
      p.peak = counts[i];
      best = i;
    }
  }
  p.argmax = 0.05 * (best - 80);
  const int lo = best - 20 >= 0 ? counts[best - 20] : 0, hi = best + 20 < int(counts.size()) ? counts[best + 20] : 0;
  p.drop = p.peak - std::max(lo, hi);
  return p;
}

// The road points' containment along the heading from the truth: the offsets at which the count of
// points more than 0.2 m outside the drivable area stays within 1 % of the points (at least 5) of its
// lowest, as the first and last of them (NaN both when the truth itself is not among them).
std::pair<double, double> containment(const BoundaryDistance& b, const std::vector<Eigen::Vector2d>& road, const Eigen::Vector3d& truth) {
  const Eigen::Vector2d a(std::cos(truth.z()), std::sin(truth.z()));
  std::vector<int> off;
  for (int i = -80; i <= 80; ++i) {
    Eigen::Vector3d pose = truth;
    pose.head<2>() += 0.05 * i * a;
    int n = 0;
    for (const Eigen::Vector2d& p : road)
      if (!(b.distance(place(pose, p)) <= kBand)) ++n;
    off.push_back(n);
  }
  const int lowest = *std::min_element(off.begin(), off.end());
  const int allowed = lowest + std::max(5, int(0.01 * double(road.size())));
  if (off[80] > allowed) return {NAN, NAN};
  int lo = 160, hi = 0;
  for (int i = 0; i <= 160; ++i)
    if (off[i] <= allowed) lo = std::min(lo, i), hi = std::max(hi, i);
  return {0.05 * (lo - 80), 0.05 * (hi - 80)};
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: probe_along_curbs LOG CONFIG\n");
    return 2;
  }
  const ArgoverseLog log(argv[1]);
  const Config config = loadConfig(argv[2]);
  const std::unique_ptr<HdMap> map = loadPriorMap(log, config);
  const BoundaryDistance& boundary = map->boundaryDistance();
  const PipelineRun run = runPipeline(log, config);
  const SweepOf sweepOf = [&](size_t frame) { return log.sweep(run.sweepOfFrame(frame)); };
  std::printf("# log %s\n# kf status curbs cross_at_truth peak_truth argmax_truth drop_truth argmax_est drop_est match_along_err contain_lo contain_hi off_at_truth_share\n",
              log.id().c_str());
  for (const KeyframeMatch& m : run.matches) {
    if (m.match.status == MatchStatus::Rejected) continue;
    const KeyframeSweep sweep = keyframeSweep(*run.odometry, m.keyframe, run.cityTOdom, sweepOf);
    const PlanarRoadPoints points = sweepRoadPoints(*sweep.sweep, sweep.egoLevel, config.roadPoints);
    const Eigen::Vector3d truth = planarPose(run.groundTruth.at(m.timestampNs));
    const Eigen::Vector2d heading(std::cos(truth.z()), std::sin(truth.z()));
    int cross = 0;
    const double h = boundary.geometry().resolution;
    for (const Eigen::Vector2d& p : points.curb) {
      const Eigen::Vector2d q = place(truth, p);
      const double d = boundary.distance(q);
      if (!std::isfinite(d) || std::abs(d) > kBand) continue;
      const Eigen::Vector2d g(boundary.distance(q + Eigen::Vector2d(h, 0)) - boundary.distance(q - Eigen::Vector2d(h, 0)),
                              boundary.distance(q + Eigen::Vector2d(0, h)) - boundary.distance(q - Eigen::Vector2d(0, h)));
      if (g.allFinite() && g.norm() > 0 && std::abs(g.normalized().dot(heading)) > std::sqrt(0.5)) ++cross;
    }
    const Profile t = profile(boundary, points.curb, truth, truth.z());
    const Profile e = profile(boundary, points.curb, m.match.estimate, truth.z());
    const Eigen::Vector2d err = m.match.estimate.head<2>() - truth.head<2>();
    const auto [lo, hi] = containment(boundary, points.road, truth);
    int offAtTruth = 0;
    std::map<std::pair<int, int>, int> offCells;  // 5 m cells of the vehicle frame
    for (const Eigen::Vector2d& p : points.road)
      if (!(boundary.distance(place(truth, p)) <= kBand)) {
        ++offAtTruth;
        ++offCells[{int(std::floor(p.x() / 5)), int(std::floor(p.y() / 5))}];
      }
    if (std::getenv("PROBE_OFF_CELLS")) {
      std::printf("# off at truth, 5 m cells (x forward, y left):");
      for (const auto& [cell, n] : offCells) std::printf(" (%d,%d):%d", 5 * cell.first, 5 * cell.second, n);
      std::printf("\n");
    }
    std::printf("%3zu %-10s %5zu %4d %4d %+6.2f %4d %+6.2f %4d %+6.2f %+6.2f %+6.2f %5.3f\n", m.keyframe, toString(m.match.status),
                points.curb.size(), cross, t.peak, t.argmax, t.drop, e.argmax, e.drop, err.dot(heading), lo, hi,
                offAtTruth / double(std::max<size_t>(points.road.size(), 1)));
  }
  return 0;
} catch (const hdprior::Error& e) {
  std::fprintf(stderr, "probe_along_curbs: %s\n", e.what());
  return 2;
}
