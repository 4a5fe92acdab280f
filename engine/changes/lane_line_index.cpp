#include "engine/changes/lane_line_index.h"

#include <cmath>

#include "engine/geom/polygon2d.h"

namespace hdprior {

namespace {

using Vec2 = Eigen::Vector2d;

int64_t bucketKey(int64_t col, int64_t row) { return (col << 32) ^ (row & 0xffffffff); }

}  // namespace

LaneLineIndex::LaneLineIndex(const VectorMap& map) {
  for (const LaneSegment& lane : map.laneSegments)
    for (const auto& [line, type] : {std::pair{&lane.leftLaneBoundary, &lane.leftLaneMarkType},
                                     std::pair{&lane.rightLaneBoundary, &lane.rightLaneMarkType}})
      for (size_t i = 0; i + 1 < line->size(); ++i) {
        const Vec2 a = (*line)[i].head<2>(), b = (*line)[i + 1].head<2>();
        if ((b - a).norm() < 1e-6) continue;
        const uint32_t k = uint32_t(segments_.size());
        segments_.push_back({a, b, isPaintedMark(*type)});
        const Vec2 lo = a.cwiseMin(b) / kBucket, hi = a.cwiseMax(b) / kBucket;
        for (int64_t c = int64_t(std::floor(lo.x())); c <= int64_t(std::floor(hi.x())); ++c)
          for (int64_t r = int64_t(std::floor(lo.y())); r <= int64_t(std::floor(hi.y())); ++r) buckets_[bucketKey(c, r)].push_back(k);
      }
}

template <typename Visit>
void LaneLineIndex::forSegmentsNear(const Vec2& city, double reach, Visit&& visit) const {
  const Vec2 lo = (city.array() - reach) / kBucket, hi = (city.array() + reach) / kBucket;
  for (int64_t c = int64_t(std::floor(lo.x())); c <= int64_t(std::floor(hi.x())); ++c)
    for (int64_t r = int64_t(std::floor(lo.y())); r <= int64_t(std::floor(hi.y())); ++r) {
      const auto it = buckets_.find(bucketKey(c, r));
      if (it == buckets_.end()) continue;
      for (uint32_t k : it->second) visit(segments_[k]);
    }
}

bool LaneLineIndex::nearPainted(const Vec2& city, double reach) const {
  bool near = false;
  forSegmentsNear(city, reach, [&](const Segment& s) { near = near || (s.painted && segmentDistance(city, city, s.a, s.b) <= reach); });
  return near;
}

std::optional<Vec2> LaneLineIndex::directionAt(const Vec2& city, double reach) const {
  double best = reach;
  std::optional<Vec2> direction;
  forSegmentsNear(city, reach, [&](const Segment& s) {
    const double d = segmentDistance(city, city, s.a, s.b);
    if (d <= best) best = d, direction = (s.b - s.a).normalized();
  });
  return direction;
}

}  // namespace hdprior
