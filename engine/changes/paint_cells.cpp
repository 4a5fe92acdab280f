#include "engine/changes/paint_cells.h"

#include <algorithm>
#include <cmath>

namespace hdprior {

double paintEvidence(const PaintTally& t, double asphaltShare, double contrast, double minShare) {
  const double s0 = std::clamp(asphaltShare, 0.005, 0.5);
  const double s1 = std::min(0.95, std::max(contrast * s0, minShare));
  return t.painted * std::log(s1 / s0) + (t.road - t.painted) * std::log((1.0 - s1) / (1.0 - s0));
}

double evidenceConfidence(double evidence) { return 1.0 / (1.0 + std::exp(-std::abs(evidence))); }

int64_t PaintCells::keyOf(const Eigen::Vector2d& city) const {
  const int64_t col = int64_t(std::floor(city.x() / size_)), row = int64_t(std::floor(city.y() / size_));
  return (col << 32) ^ (row & 0xffffffff);
}

std::pair<PaintCell&, bool> PaintCells::at(const Eigen::Vector2d& city) {
  const auto [it, inserted] = cells_.try_emplace(keyOf(city));
  return {it->second, inserted};
}

const PaintCell* PaintCells::find(const Eigen::Vector2d& city) const {
  const auto it = cells_.find(keyOf(city));
  return it == cells_.end() ? nullptr : &it->second;
}

}  // namespace hdprior
