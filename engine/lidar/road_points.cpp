#include "engine/lidar/road_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include "engine/error.h"

namespace hdprior {
namespace {

void validate(const RoadPointOptions& o) {
  RoadPointOptions keys = o;
  checkOptionRanges("road point options", optionFields(keys));
  if (!(o.maxSkipped >= 0 && o.gutterWindow > 0 && o.seedTolerancePerMetre >= 0 && o.laneStep > 0 && o.gradeLength > 0 &&
        o.laneObjectHeight > o.laneStep)) {
    throw Error("road point options", "maxSkipped, gutterWindow, seedTolerancePerMetre or lane settings out of range (laneObjectHeight must be above laneStep)");
  }
}

constexpr double kDenseSpacing = 0.5;  // metres between consecutive points of a ring
constexpr double kOccluderHeight = 0.3;  // metres above the road: an object's side, higher than a kerb's face

// The lowest non-ground return in each cell of a square grid around the vehicle: where the walk
// meets a step, an object standing on it (a parked car's side, classed as ground near its foot)
// tells the step from a kerb, above whose top nothing stands.
class ObjectFloor {
 public:
  ObjectFloor(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> ground, double range)
      : side_(2 * long(std::ceil(range / kCell))), lowest_(size_t(side_ * side_), kNone) {
    for (size_t i = 0; i < points.size(); ++i) {
      if (ground[i] || !points[i].allFinite()) continue;
      const long c = cell(points[i]);
      if (c >= 0) lowest_[size_t(c)] = std::min(lowest_[size_t(c)], float(points[i].z()));
    }
  }

  // A non-ground return within a cell of p, between kAbove and kBelow above it (a car's side, not a
  // tree's canopy).
  bool standsOn(const Eigen::Vector3d& p) const {
    for (double dx : {-kCell, 0.0, kCell}) {
      for (double dy : {-kCell, 0.0, kCell}) {
        const long c = cell(p + Eigen::Vector3d(dx, dy, 0.0));
        if (c >= 0 && lowest_[size_t(c)] > p.z() + kAbove && lowest_[size_t(c)] < p.z() + kBelow) return true;
      }
    }
    return false;
  }

 private:
  static constexpr double kCell = 0.25, kAbove = 0.1, kBelow = 1.5;  // metres
  static constexpr float kNone = std::numeric_limits<float>::infinity();
  long cell(const Eigen::Vector3d& p) const {
    const long col = long(std::floor(p.x() / kCell)) + side_ / 2, row = long(std::floor(p.y() / kCell)) + side_ / 2;
    return col >= 0 && row >= 0 && col < side_ && row < side_ ? row * side_ + col : -1;
  }
  long side_;
  std::vector<float> lowest_;
};

// The ground points of one ring in azimuth order, and the walk over them.
class RingWalk {
 public:
  RingWalk(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> seeds, std::vector<uint32_t> members,
           std::vector<uint32_t> occluders, const ObjectFloor& objects, const RoadPointOptions& o)
      : points_(points), seeds_(seeds), members_(std::move(members)), occluders_(std::move(occluders)),
        objects_(objects), o_(o) {
    azimuth_.reserve(members_.size());
    for (uint32_t i : members_) azimuth_.push_back(std::atan2(points_[i].y(), points_[i].x()));
    std::vector<size_t> order(members_.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return azimuth_[a] != azimuth_[b] ? azimuth_[a] < azimuth_[b] : members_[a] < members_[b];
    });
    std::vector<uint32_t> m;
    std::vector<double> az;
    for (size_t k : order) {
      m.push_back(members_[k]);
      az.push_back(azimuth_[k]);
    }
    members_ = std::move(m);
    azimuth_ = std::move(az);
    visited_.assign(members_.size(), 0);
  }

  void walk(std::vector<uint8_t>& road) {
    const size_t n = members_.size();
    if (n == 0) return;
    for (size_t k = 0; k < n; ++k) {
      if (visited_[k] || !seeds_[members_[k]]) continue;
      visited_[k] = 1;
      road[members_[k]] = 1;
      walkFrom(k, +1, road);
      walkFrom(k, -1, road);
    }
  }

 private:
  // Steps along the ring while each ground point's height agrees with every road point of
  // this walk within `window` metres behind it (so a curb climbed through its face points,
  // in steps each below maxStep, still ends the walk); up to maxSkipped consecutive points
  // that disagree (noise) are skipped before the walk ends.
  void walkFrom(size_t start, int direction, std::vector<uint8_t>& road) {
    const size_t n = members_.size();
    std::vector<size_t> path = {start};
    int failures = 0;
    size_t k = start, firstFailure = start;
    for (size_t steps = 1; steps < n; ++steps) {
      k = (k + n + size_t(direction)) % n;
      if (visited_[k]) return;
      const Eigen::Vector3d& b = points_[members_[k]];
      if ((b.head<2>() - points_[members_[path.back()]].head<2>()).norm() > o_.maxGap) return;
      if (!agrees(b, path) || climbsOutOfGutter(b, path)) {
        if (failures == 0) firstFailure = k;
        if (++failures > o_.maxSkipped) {
          // Ended by a height step, not a gap: the last road point lies at a curb, unless the step
          // was not seen (an object stood between) or is an object's foot (a parked car's side).
          if (path.size() > 1 && !occludedBetween(path.back(), firstFailure, direction) &&
              !objects_.standsOn(points_[members_[firstFailure]])) {
            road[members_[path.back()]] = kCurbPoint;
          }
          return;
        }
        continue;
      }
      failures = 0;
      visited_[k] = 1;
      road[members_[k]] = 1;
      path.push_back(k);
    }
  }

  // b agrees with the walk's road points within `window` behind it once the road's cross slope there
  // (camber) is taken out: b's height is compared with each point's raised along that slope.
  bool agrees(const Eigen::Vector3d& b, const std::vector<size_t>& path) const {
    // Only where the ring samples the surface densely: across a gap (a ring grazing a kerb) a step
    // would hide in the slope.
    const bool dense = (b.head<2>() - points_[members_[path.back()]].head<2>()).norm() <= kDenseSpacing;
    const double slope = dense ? crossSlope(path) : 0.0;
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      const Eigen::Vector3d& a = points_[members_[*it]];
      const double distance = (b.head<2>() - a.head<2>()).norm();
      if (it != path.rbegin() && distance > o_.window) break;
      if (std::abs(b.z() - a.z() - slope * distance) > o_.maxStep + o_.stepPerMetre * distance) return false;
    }
    return true;
  }

  // b is gutterRise above the walk's lowest point within gutterWindow behind it, and a point of the
  // walk before that low (within `window`) is gutterRise above it too: a V, b on its far side. The
  // walk's heights are taken as the mean of three consecutive points, so that range noise (1-2 cm)
  // does not make a V of its own.
  bool climbsOutOfGutter(const Eigen::Vector3d& b, const std::vector<size_t>& path) const {
    if (o_.gutterRise <= 0.0 || path.size() < 3) return false;
    if (b.z() < lowestNear(b, path) + o_.gutterRise) return false;  // the usual case, in a third of the scan
    double low = b.z();
    bool lowNear = true;
    for (size_t j = path.size() - 1; j >= 2; --j) {
      const Eigen::Vector3d& a = points_[members_[path[j]]];
      const double distance = (b.head<2>() - a.head<2>()).norm();
      if (distance > o_.window) break;
      const double z = smoothedHeight(path, j);
      if (z < low) {
        low = z;
        lowNear = distance <= o_.gutterWindow;
      } else if (lowNear && z >= low + o_.gutterRise) {
        return b.z() >= low + o_.gutterRise;
      }
    }
    return false;
  }

  // Whether a return of this ring higher than kOccluderHeight above road point `from` lies between it
  // and ground point `to`, walking in `direction` of azimuth. A scan of the ring's non-ground returns
  // by pseudo-angle: a few walks per ring end at a step, and sorting them all cost more (4 ms a sweep).
  bool occludedBetween(size_t from, size_t to, int direction) const {
    double a = pseudoAngle(points_[members_[from]]), b = pseudoAngle(points_[members_[to]]);
    if (direction < 0) std::swap(a, b);
    const double minZ = points_[members_[from]].z() + kOccluderHeight;
    for (uint32_t i : occluders_) {
      if (points_[i].z() <= minZ) continue;
      const double p = pseudoAngle(points_[i]);
      if (a <= b ? (p > a && p < b) : (p > a || p < b)) return true;
    }
    return false;
  }

  // Increases with the azimuth from the x axis round to it again, in [0, 4).
  static double pseudoAngle(const Eigen::Vector3d& p) {
    const double r = p.x() / (std::abs(p.x()) + std::abs(p.y()) + 1e-300);
    return p.y() >= 0.0 ? 1.0 - r : 3.0 + r;
  }

  // The mean height of the walk's points j-2, j-1 and j.
  double smoothedHeight(const std::vector<size_t>& path, size_t j) const {
    return (points_[members_[path[j]]].z() + points_[members_[path[j - 1]]].z() + points_[members_[path[j - 2]]].z()) / 3.0;
  }

  // The lowest of the walk's smoothed heights within gutterWindow behind b.
  double lowestNear(const Eigen::Vector3d& b, const std::vector<size_t>& path) const {
    double low = b.z();
    for (size_t j = path.size() - 1; j >= 2; --j) {
      const Eigen::Vector3d& a = points_[members_[path[j]]];
      if ((b.head<2>() - a.head<2>()).norm() > o_.gutterWindow) break;
      low = std::min(low, smoothedHeight(path, j));
    }
    return low;
  }

  // The walk's height gain per metre over its last `window` metres, within +-maxCamber (a kerb's face
  // climbed in small steps must not become a slope that lets its top through).
  double crossSlope(const std::vector<size_t>& path) const {
    if (o_.maxCamber <= 0.0 || path.size() < 2) return 0.0;
    const Eigen::Vector3d& last = points_[members_[path.back()]];
    for (auto it = path.rbegin() + 1; it != path.rend(); ++it) {
      const Eigen::Vector3d& a = points_[members_[*it]];
      const double distance = (last.head<2>() - a.head<2>()).norm();
      if (distance >= o_.window || it + 1 == path.rend()) {
        if (distance < 0.5 * o_.window) return 0.0;  // too short a run to tell a slope
        return std::clamp((last.z() - a.z()) / distance, -o_.maxCamber, o_.maxCamber);
      }
    }
    return 0.0;
  }

  std::span<const Eigen::Vector3d> points_;
  std::span<const uint8_t> seeds_;
  std::vector<uint32_t> members_;
  std::vector<double> azimuth_;
  std::vector<uint32_t> occluders_;  // the ring's non-ground returns
  const ObjectFloor& objects_;
  std::vector<uint8_t> visited_;
  const RoadPointOptions& o_;
};

// The lane's height profile: a line z = a + b |x| through the lane's points within `length` metres
// before the next one (and the vehicle's own ground (0, groundZ) while they are too few or too
// bunched to give a grade), so a climbing road is followed.
class LaneProfile {
 public:
  LaneProfile(double groundZ, double length) : groundZ_(groundZ), length_(length) {}

  void add(double ax, double z) {
    window_.push_back({ax, z});
    sums_ += Sums::of(ax, z);
  }

  double predict(double ax) {
    while (!window_.empty() && window_.front().x() < ax - length_) {
      sums_ -= Sums::of(window_.front().x(), window_.front().y());
      window_.pop_front();
    }
    // Anchoring far-out windows at the vehicle too would bend the profile of a road whose grade
    // changes (a sag) below the road, and end the lane there (the real sweeps, 33 m behind).
    Sums s = sums_;
    if (s.n < 2 || s.xx / s.n - (s.x / s.n) * (s.x / s.n) < 1.0) s += Sums::of(0.0, groundZ_);  // spread < 2 m: no grade of its own
    const double det = s.n * s.xx - s.x * s.x;
    const double b = det > 1e-9 ? (s.n * s.xz - s.x * s.z) / det : 0.0;
    return (s.z - b * s.x) / s.n + b * ax;
  }

 private:
  struct Sums {  // running sums of the window's points for the least-squares line
    double n = 0, x = 0, z = 0, xx = 0, xz = 0;
    static Sums of(double x, double z) { return {1, x, z, x * x, x * z}; }
    Sums& operator+=(const Sums& o) { n += o.n, x += o.x, z += o.z, xx += o.xx, xz += o.xz; return *this; }
    Sums& operator-=(const Sums& o) { n -= o.n, x -= o.x, z -= o.z, xx -= o.xx, xz -= o.xz; return *this; }
  };
  double groundZ_, length_;
  std::deque<Eigen::Vector2d> window_;  // (|x|, z)
  Sums sums_;
};

// The seeds: ground points in the vehicle's lane (within seedHalfWidth of its x axis) at road
// level (groundZ, within the seed tolerance), only as far as the lane goes: its points are walked
// outwards ahead and behind in order of |x| along the lane's height profile, and the lane ends at the
// first rise of more than laneStep above it that persists for laneEndLength (a kerb across the road
// at a T-junction), so the rings are not walked from a sidewalk beyond it; points below the profile
// (gutters, crowns) are only skipped.
std::vector<uint8_t> laneSeeds(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> ground,
                               const RoadPointOptions& o) {
  std::vector<uint8_t> seeds(points.size(), 0);
  for (double side : {1.0, -1.0}) {
    std::vector<uint32_t> lane;
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d& p = points[i];
      if (ground[i] && p.allFinite() && side * p.x() > 0.0 && std::abs(p.y()) < o.seedHalfWidth &&
          p.head<2>().norm() < o.maxRange) {
        lane.push_back(uint32_t(i));
      }
    }
    std::sort(lane.begin(), lane.end(), [&](uint32_t a, uint32_t b) {
      const double da = std::abs(points[a].x()), db = std::abs(points[b].x());
      return da != db ? da < db : a < b;
    });
    LaneProfile profile(o.groundZ, o.gradeLength);
    double lastX = 0.0, riseFrom = -1.0;  // riseFrom: where the current run of points above the lane began
    bool started = false;
    for (uint32_t i : lane) {
      const Eigen::Vector3d& p = points[i];
      const double ax = std::abs(p.x());
      const bool level = std::abs(p.z() - o.groundZ) < o.seedTolerance + o.seedTolerancePerMetre * p.head<2>().norm();
      const double pred = started ? profile.predict(ax) : 0.0;
      // Grown with the gap to the last lane point, but not along a run above the lane (a sidewalk).
      const double tolerance = o.laneStep + o.stepPerMetre * ((riseFrom >= 0.0 ? riseFrom : ax) - lastX);
      // Below: a gutter or a crown; far above: an object on the lane (ground segmentation let it
      // through, e.g. 0.8 m up behind a real sweep). Neither is a kerb up.
      if (started && (p.z() < pred - tolerance || p.z() > pred + o.laneObjectHeight)) continue;
      const bool agrees = started ? p.z() - pred <= tolerance : level;
      if (!agrees) {
        // A ring's points near the axis share one range: a bump under one ring (0.1 m, 33 m behind a
        // real sweep) is not a kerb; a kerb's sidewalk stays up for metres.
        if (started && riseFrom < 0.0) riseFrom = ax;
        if (started && ax - riseFrom >= o.laneEndLength) break;
        continue;
      }
      started = true;
      riseFrom = -1.0;
      lastX = ax;
      profile.add(ax, p.z());
      seeds[i] = level;
    }
  }
  return seeds;
}

}  // namespace

std::vector<uint8_t> extractRoadPoints(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> ring,
                                       std::span<const uint8_t> ground, const RoadPointOptions& options) {
  validate(options);
  if (ground.size() != points.size() || ring.size() != points.size()) {
    throw Error("road points", "ring ids (" + std::to_string(ring.size()) + ") or ground flags (" +
                                   std::to_string(ground.size()) + ") do not match the points (" +
                                   std::to_string(points.size()) + ")");
  }
  std::array<std::vector<uint32_t>, 256> rings, occluders;
  for (size_t i = 0; i < points.size(); ++i) {
    if (points[i].allFinite() && points[i].head<2>().norm() < options.maxRange) {
      (ground[i] ? rings : occluders)[ring[i]].push_back(uint32_t(i));
    }
  }
  const std::vector<uint8_t> seeds = laneSeeds(points, ground, options);
  const ObjectFloor objects(points, ground, options.maxRange);
  std::vector<uint8_t> road(points.size(), 0);
  for (size_t r = 0; r < rings.size(); ++r) {
    if (!rings[r].empty()) RingWalk(points, seeds, std::move(rings[r]), std::move(occluders[r]), objects, options).walk(road);
  }
  return road;
}

std::vector<Eigen::Vector2d> planarPoints(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> flags,
                                          double cell) {
  if (flags.size() != points.size()) throw Error("planar points", "flags do not match the points");
  std::vector<Eigen::Vector2d> out;
  if (!(cell > 0.0)) {
    for (size_t i = 0; i < points.size(); ++i) {
      if (flags[i]) out.emplace_back(points[i].x(), points[i].y());
    }
    return out;
  }
  std::map<std::pair<long, long>, std::pair<Eigen::Vector2d, int>> cells;  // ordered: deterministic
  for (size_t i = 0; i < points.size(); ++i) {
    if (!flags[i] || !points[i].allFinite()) continue;
    const std::pair<long, long> key(long(std::floor(points[i].x() / cell)), long(std::floor(points[i].y() / cell)));
    auto& [sum, n] = cells.try_emplace(key, Eigen::Vector2d::Zero(), 0).first->second;
    sum += points[i].head<2>();
    ++n;
  }
  out.reserve(cells.size());
  for (const auto& [key, value] : cells) out.push_back(value.first / value.second);
  return out;
}

}  // namespace hdprior
