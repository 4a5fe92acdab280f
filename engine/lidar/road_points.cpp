#include "engine/lidar/road_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "engine/error.h"

namespace hdprior {
namespace {

void validate(const RoadPointOptions& o) {
  if (!(o.maxRange > 0 && o.maxStep > 0 && o.stepPerMetre >= 0 && o.maxGap > 0 && o.window >= 0 && o.maxSkipped >= 0 && o.seedHalfWidth > 0 && o.seedTolerance > 0 && o.seedTolerancePerMetre >= 0)) {
    throw Error("road point options", "maxRange, maxStep, stepPerMetre, maxGap or seed settings out of range");
  }
}

// The ground points of one ring in azimuth order, and the walk over them.
class RingWalk {
 public:
  RingWalk(std::span<const Eigen::Vector3d> points, std::vector<uint32_t> members, const RoadPointOptions& o)
      : points_(points), members_(std::move(members)), o_(o) {
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
      if (visited_[k] || !isSeed(members_[k])) continue;
      visited_[k] = 1;
      road[members_[k]] = 1;
      walkFrom(k, +1, road);
      walkFrom(k, -1, road);
    }
  }

 private:
  bool isSeed(uint32_t i) const {
    const Eigen::Vector3d& p = points_[i];
    return std::abs(p.y()) < o_.seedHalfWidth &&
           std::abs(p.z() - o_.groundZ) < o_.seedTolerance + o_.seedTolerancePerMetre * p.head<2>().norm();
  }

  // Steps along the ring while each ground point's height agrees with every road point of
  // this walk within `window` metres behind it (so a curb climbed through its face points,
  // in steps each below maxStep, still ends the walk); up to maxSkipped consecutive points
  // that disagree (noise) are skipped before the walk ends.
  void walkFrom(size_t start, int direction, std::vector<uint8_t>& road) {
    const size_t n = members_.size();
    std::vector<size_t> path = {start};
    int failures = 0;
    size_t k = start;
    for (size_t steps = 1; steps < n; ++steps) {
      k = (k + n + size_t(direction)) % n;
      if (visited_[k]) return;
      const Eigen::Vector3d& b = points_[members_[k]];
      if ((b.head<2>() - points_[members_[path.back()]].head<2>()).norm() > o_.maxGap) return;
      if (!agrees(b, path)) {
        if (++failures > o_.maxSkipped) {
          // Ended by a height step, not a gap: the last road point lies at a curb.
          if (path.size() > 1) road[members_[path.back()]] = kCurbPoint;
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

  bool agrees(const Eigen::Vector3d& b, const std::vector<size_t>& path) const {
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      const Eigen::Vector3d& a = points_[members_[*it]];
      const double distance = (b.head<2>() - a.head<2>()).norm();
      if (it != path.rbegin() && distance > o_.window) break;
      if (std::abs(b.z() - a.z()) > o_.maxStep + o_.stepPerMetre * distance) return false;
    }
    return true;
  }

  std::span<const Eigen::Vector3d> points_;
  std::vector<uint32_t> members_;
  std::vector<double> azimuth_;
  std::vector<uint8_t> visited_;
  const RoadPointOptions& o_;
};

}  // namespace

std::vector<uint8_t> extractRoadPoints(std::span<const Eigen::Vector3d> points, std::span<const uint8_t> ring,
                                       std::span<const uint8_t> ground, const RoadPointOptions& options) {
  validate(options);
  if (ground.size() != points.size() || ring.size() != points.size()) {
    throw Error("road points", "ring ids (" + std::to_string(ring.size()) + ") or ground flags (" +
                                   std::to_string(ground.size()) + ") do not match the points (" +
                                   std::to_string(points.size()) + ")");
  }
  std::array<std::vector<uint32_t>, 256> rings;
  for (size_t i = 0; i < points.size(); ++i) {
    if (ground[i] && points[i].allFinite() && points[i].head<2>().norm() < options.maxRange) {
      rings[ring[i]].push_back(uint32_t(i));
    }
  }
  std::vector<uint8_t> road(points.size(), 0);
  for (std::vector<uint32_t>& members : rings) {
    if (!members.empty()) RingWalk(points, std::move(members), options).walk(road);
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
