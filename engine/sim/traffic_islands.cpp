#include "engine/sim/traffic_islands.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <unordered_map>

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

// Points with a direction, hashed in square cells for queries within one cell size.
class PointHash {
 public:
  explicit PointHash(double cell) : cell_(cell) {}
  void add(const Vec2& p, const Vec2& dir) {
    cells_[key(int64_t(std::floor(p.x() / cell_)), int64_t(std::floor(p.y() / cell_)))].push_back(points_.size());
    points_.push_back({p, dir});
  }
  // The nearest point within `radius` (<= cell size).
  std::optional<std::pair<Vec2, Vec2>> nearest(const Vec2& p, double radius) const {
    const int64_t cx = int64_t(std::floor(p.x() / cell_)), cy = int64_t(std::floor(p.y() / cell_));
    double best = radius * radius;
    std::optional<std::pair<Vec2, Vec2>> out;
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (size_t i : it->second) {
          const double d = (points_[i].first - p).squaredNorm();
          if (d <= best) {
            best = d;
            out = points_[i];
          }
        }
      }
    return out;
  }

 private:
  static int64_t key(int64_t x, int64_t y) { return (x << 32) ^ int64_t(uint32_t(int32_t(y))); }
  double cell_;
  std::unordered_map<int64_t, std::vector<size_t>> cells_;
  std::vector<std::pair<Vec2, Vec2>> points_;
};

}  // namespace

std::vector<TrafficIsland> placeTrafficIslands(const BoundaryDistance& mapDistance, const LaneGraph& lanes,
                                               std::span<const Vec2> egoPath, const Vec2& lo, const Vec2& hi,
                                               double density, uint64_t seed) {
  std::vector<TrafficIsland> out;
  if (density <= 0.0) return out;
  std::mt19937_64 rng(seed ^ 0x151a4d5ULL);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto inRegion = [&](const Vec2& p) { return (p.array() >= lo.array() - 30.0).all() && (p.array() <= hi.array() + 30.0).all(); };
  PointHash lanePoints(8.0), egoPoints(8.0);
  for (const Lane& lane : lanes.lanes())
    for (size_t i = 0; i + 1 < lane.centerline.size(); ++i) {
      const Vec2 p = lane.centerline[i].head<2>(), q = lane.centerline[i + 1].head<2>();
      if (!inRegion(p) || (q - p).norm() < 1e-9) continue;
      const int n = std::max(1, int(std::ceil((q - p).norm() / 0.5)));
      for (int k = 0; k < n; ++k) lanePoints.add(p + (q - p) * double(k) / n, (q - p).normalized());
    }
  for (const Vec2& p : egoPath) egoPoints.add(p, Vec2::UnitX());

  std::vector<Vec2> candidates;
  for (double y = std::ceil(lo.y() / 4.0) * 4.0; y <= hi.y(); y += 4.0)
    for (double x = std::ceil(lo.x() / 4.0) * 4.0; x <= hi.x(); x += 4.0) {
      const double d = mapDistance.distance({x, y});
      if (d < -3.0) candidates.emplace_back(x, y);
    }
  std::shuffle(candidates.begin(), candidates.end(), rng);
  for (const Vec2& c : candidates) {
    const double keep = unit(rng), radius = 0.4 + 0.6 * unit(rng), halfLength = 3.0 + 9.0 * unit(rng);
    if (keep >= density || out.size() >= 80) continue;
    const auto lane = lanePoints.nearest(c, 8.0);
    if (!lane) continue;
    const Vec2 dir = lane->second;
    bool near = false;
    for (const TrafficIsland& t : out) near |= (0.5 * (t.a + t.b) - c).norm() < 30.0;
    if (near) continue;
    const TrafficIsland island{c - halfLength * dir, c + halfLength * dir, radius};
    bool ok = true;
    const int n = int(std::ceil(2.0 * halfLength));
    for (int k = 0; k <= n && ok; ++k) {
      const Vec2 axis = island.a + (island.b - island.a) * double(k) / n;
      const Vec2 side(-dir.y(), dir.x());
      for (double s : {-radius, 0.0, radius}) {
        const double d = mapDistance.distance(axis + s * side);
        ok &= !std::isnan(d) && d < -1.0;
      }
      ok &= !lanePoints.nearest(axis, radius + 1.5) && !egoPoints.nearest(axis, radius + 3.0);
    }
    if (ok) out.push_back(island);
  }
  return out;
}

}  // namespace hdprior
