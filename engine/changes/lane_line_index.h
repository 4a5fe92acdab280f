#pragma once
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "engine/io/vector_map.h"

namespace hdprior {

// The map's lane boundaries as segments in 5 m buckets, for the paint checks' look-ups near a point.
class LaneLineIndex {
 public:
  explicit LaneLineIndex(const VectorMap& map);

  // Whether a painted boundary (isPaintedMark) passes within `reach` metres (at most 5) of the point.
  bool nearPainted(const Eigen::Vector2d& city, double reach) const;
  // The direction of the boundary nearest to the point within `reach` metres, painted or not.
  std::optional<Eigen::Vector2d> directionAt(const Eigen::Vector2d& city, double reach) const;

 private:
  struct Segment {
    Eigen::Vector2d a, b;
    bool painted;
  };
  static constexpr double kBucket = 5.0;
  template <typename Visit>
  void forSegmentsNear(const Eigen::Vector2d& city, double reach, Visit&& visit) const;

  std::vector<Segment> segments_;
  std::unordered_map<int64_t, std::vector<uint32_t>> buckets_;
};

}  // namespace hdprior
