#include "engine/sim/trajectory.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "engine/error.h"
#include "engine/geom/planar_difference.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr int64_t kMarginNs = 150'000'000;  // poses beyond the last sweep's end

struct Station {
  Vec2 xy;
  double s = 0.0, vmax = 0.0;
  bool stop = false;
};

// The route resampled every ~0.5 m, with junction entries marked.
std::vector<Station> routeStations(const LaneGraph& lanes, const std::vector<size_t>& route) {
  std::vector<Station> out;
  for (size_t k = 0; k < route.size(); ++k) {
    const Lane& lane = lanes.lanes()[route[k]];
    const Polyline3 line = resampleByArcLength(lane.centerline, std::max<size_t>(2, size_t(lane.length / 0.5) + 1));
    const bool entersJunction = lane.isIntersection && (k == 0 || !lanes.lanes()[route[k - 1]].isIntersection);
    for (size_t i = (out.empty() ? 0 : 1); i < line.size(); ++i) {
      Station st;
      st.xy = line[i].head<2>();
      st.s = out.empty() ? 0.0 : out.back().s + (st.xy - out.back().xy).norm();
      st.stop = entersJunction && i == 1;
      if (st.s > 0.0 && !out.empty() && st.s - out.back().s < 1e-6) continue;
      out.push_back(st);
    }
  }
  return out;
}

// Lane centerlines are polylines (a junction connector has a vertex every ~2 m): driven as they
// are, the heading would jump by several degrees at each vertex. A car's path is smooth: each
// station becomes the triangle-weighted mean of the stations within halfWindow along the route
// (the window shrinks symmetrically at the ends, so they stay put).
void smoothPath(std::vector<Station>& st, double halfWindow) {
  std::vector<Vec2> xy(st.size());
  const auto n = std::ptrdiff_t(st.size());
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const double w = std::min({halfWindow, st[i].s - st.front().s, st.back().s - st[i].s});
    Vec2 sum = st[i].xy;
    double weight = 1.0;
    for (std::ptrdiff_t dir : {-1, 1}) {
      for (std::ptrdiff_t k = i + dir; k >= 0 && k < n && std::abs(st[k].s - st[i].s) < w; k += dir) {
        const double c = 1.0 - std::abs(st[k].s - st[i].s) / w;
        sum += c * st[k].xy;
        weight += c;
      }
    }
    xy[i] = sum / weight;
  }
  for (size_t i = 0; i < st.size(); ++i) {
    st[i].xy = xy[i];
    if (i > 0) st[i].s = st[i - 1].s + (xy[i] - xy[i - 1]).norm();
  }
}

double headingAt(const std::vector<Station>& st, size_t i, double reach) {
  size_t a = i, b = i;
  while (a > 0 && st[i].s - st[a].s < reach) --a;
  while (b + 1 < st.size() && st[b].s - st[i].s < reach) ++b;
  const Vec2 d = st[b].xy - st[a].xy;
  return std::atan2(d.y(), d.x());
}

}  // namespace

PoseTrajectory routeTrajectory(const LaneGraph& lanes, const GroundHeight& ground, const RouteOptions& o,
                               uint64_t seed) {
  if (!(o.seconds > 0.0) || !(o.cruiseSpeed > 0.0) || !(o.poseRateHz >= 100.0))
    throw Error("route options", "seconds and speed must be positive and the pose rate at least 100 Hz");
  std::mt19937_64 rng(seed ^ 0x7a3e11ULL);
  std::vector<size_t> starts;
  for (size_t i = 0; i < lanes.lanes().size(); ++i) {
    const Lane& l = lanes.lanes()[i];
    if (!l.isIntersection && l.length > 20.0 && (l.laneType.empty() || l.laneType == "VEHICLE")) starts.push_back(i);
  }
  if (starts.empty()) throw Error("lane graph", "no lane of at least 20 m to start a route on");
  const double needed = o.cruiseSpeed * (o.seconds + 1.0) + 20.0;
  std::vector<Station> st;
  for (int attempt = 0; attempt < 50 && (st.empty() || st.back().s < needed); ++attempt) {
    const size_t start = starts[std::uniform_int_distribution<size_t>(0, starts.size() - 1)(rng)];
    st = routeStations(lanes, lanes.randomRoute(start, needed, rng));
    // A real map's ground height ends a few metres beyond its drivable area: cut the route there.
    const auto off = std::find_if(st.begin(), st.end(), [&](const Station& x) { return std::isnan(ground.bilinearAt(x.xy)); });
    st.erase(off, st.end());
    for (int pass = 0; pass < 2; ++pass) smoothPath(st, 2.0);
  }
  if (st.size() < 2 || st.back().s < needed)
    throw Error("lane graph", "no route of " + std::to_string(int(needed)) + " m along the lanes (within the ground height)");

  // Speed limits from curvature, stops, then acceleration-limited forward/backward passes.
  std::bernoulli_distribution stopHere(o.stopProbability);
  for (size_t i = 0; i < st.size(); ++i) {
    size_t a = i, b = i;
    while (a > 0 && st[i].s - st[a].s < 4.0) --a;
    while (b + 1 < st.size() && st[b].s - st[i].s < 4.0) ++b;
    double turn = wrappedAngle(headingAt(st, b, 2.0) - headingAt(st, a, 2.0));
    const double curvature = std::abs(turn) / std::max(1.0, st[b].s - st[a].s);
    st[i].vmax = std::min(o.cruiseSpeed, std::sqrt(o.lateralAccel / std::max(curvature, 1e-6)));
    st[i].vmax = std::max(st[i].vmax, 2.0);
    if (st[i].stop && i > 0 && stopHere(rng)) st[i].vmax = 0.0;
    else st[i].stop = false;
  }
  std::vector<double> v(st.size());
  v[0] = st[0].vmax;
  for (size_t i = 1; i < st.size(); ++i)
    v[i] = std::min(st[i].vmax, std::sqrt(v[i - 1] * v[i - 1] + 2 * o.accel * (st[i].s - st[i - 1].s)));
  for (size_t i = st.size() - 1; i-- > 0;)
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * o.accel * (st[i + 1].s - st[i].s)));

  // Time at each station (a stop waits stopSeconds), then poses at a fixed rate.
  std::vector<double> T(st.size(), 0.0), S(st.size(), 0.0);
  std::vector<double> knotT, knotS;
  knotT.push_back(0.0);
  knotS.push_back(0.0);
  double t = 0.0;
  for (size_t i = 1; i < st.size(); ++i) {
    const double ds = st[i].s - st[i - 1].s;
    t += ds / std::max(0.25, 0.5 * (v[i] + v[i - 1]));
    knotT.push_back(t);
    knotS.push_back(st[i].s);
    if (st[i].stop) {
      t += o.stopSeconds;
      knotT.push_back(t);
      knotS.push_back(st[i].s);
    }
  }
  const int64_t durationNs = int64_t(std::llround(o.seconds * 1e9)) + kMarginNs;
  if (knotT.back() * 1e9 < double(durationNs))
    throw Error("lane graph", "route too short for " + std::to_string(o.seconds) + " s");
  const int64_t stepNs = int64_t(std::llround(1e9 / o.poseRateHz));
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  size_t k = 0, j = 0;
  for (int64_t dt = 0; dt <= durationNs; dt += stepNs) {
    const double tt = double(dt) * 1e-9;
    while (k + 2 < knotT.size() && knotT[k + 1] <= tt) ++k;
    const double f = knotT[k + 1] > knotT[k] ? std::clamp((tt - knotT[k]) / (knotT[k + 1] - knotT[k]), 0.0, 1.0) : 1.0;
    const double s = knotS[k] + f * (knotS[k + 1] - knotS[k]);
    while (j + 2 < st.size() && st[j + 1].s <= s) ++j;
    const double g = std::clamp((s - st[j].s) / std::max(1e-9, st[j + 1].s - st[j].s), 0.0, 1.0);
    const Vec2 xy = (1 - g) * st[j].xy + g * st[j + 1].xy;
    const double yaw0 = headingAt(st, j, 1.0);
    const double yaw = yaw0 + g * wrappedAngle(headingAt(st, j + 1, 1.0) - yaw0);
    const double z = ground.bilinearAt(xy);
    if (std::isnan(z)) throw Error(ground.source(), "no ground height under the route");
    RollPitch rp = ground.rollPitchAt(xy, yaw, 2.0);
    if (std::isnan(rp.roll) || std::isnan(rp.pitch)) rp = {0.0, 0.0};
    const Eigen::Quaterniond q = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(rp.pitch, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(rp.roll, Eigen::Vector3d::UnitX());
    stamps.push_back(o.startNs + dt);
    poses.push_back(makeSE3(q, Eigen::Vector3d(xy.x(), xy.y(), z + o.egoHeight)));
  }
  return PoseTrajectory(std::move(stamps), std::move(poses), "route");
}

PoseTrajectory cropTrajectory(const PoseTrajectory& poses, double seconds) {
  if (poses.size() < 2) throw Error("trajectory", "fewer than two poses");
  const int64_t end = seconds > 0.0 ? poses.startNs() + int64_t(std::llround(seconds * 1e9)) + kMarginNs : poses.endNs();
  if (end > poses.endNs())
    throw Error("option --seconds", "the log's poses span only " +
                                        std::to_string(double(poses.endNs() - poses.startNs() - kMarginNs) * 1e-9) + " s");
  std::vector<int64_t> t;
  std::vector<SE3> p;
  for (size_t i = 0; i < poses.size() && poses.timestamps()[i] < end; ++i) {
    t.push_back(poses.timestamps()[i]);
    p.push_back(poses.poses()[i]);
  }
  t.push_back(end);
  p.push_back(poses.at(end));
  return PoseTrajectory(std::move(t), std::move(p), "real poses");
}

}  // namespace hdprior
