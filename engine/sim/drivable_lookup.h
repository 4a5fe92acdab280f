#pragma once
#include <vector>

#include "engine/geom/polygon2d.h"
#include "engine/io/vector_map.h"

namespace hdprior {

// Whether a point lies on a map's drivable area: each polygon's even-odd rule, OR over the
// polygons (bounding boxes first).
class DrivableLookup {
 public:
  explicit DrivableLookup(const VectorMap& map);
  bool contains(const Eigen::Vector2d& p) const;

 private:
  struct Entry {
    Ring2 ring;
    Eigen::Vector2d lo, hi;
  };
  std::vector<Entry> rings_;
};

}  // namespace hdprior
