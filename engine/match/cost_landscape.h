#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/map/ndt_score.h"
#include "engine/match/match_options.h"

namespace hdprior {

class HdMap;
class NdtGrid;

struct CostLandscapeOptions {
  double halfExtent = 3.0;   // metres: offsets in [-halfExtent, +halfExtent] along x and y ...
  double step = 0.1;         // ... every step metres (city axes, centred on the pose)
  double yawHalfDeg = 5.0;   // the yaw profile: offsets in [-yawHalfDeg, +yawHalfDeg] ...
  double yawStepDeg = 0.25;  // ... every yawStepDeg
  NdtScoreParams score;      // outlier ratio, as the matcher's finest level
  int threads = 2;           // rows are scored in parallel (the result does not depend on it)
};

// The NDT score of a set of road points (key-frame frame) over a grid of poses around `center`
// (x, y, yaw in the city): scores(row, col) at (center.x + x(col), center.y + y(row), center.yaw),
// and the score over yaw offsets at (center.x, center.y). What the tuning bench draws as a heat map:
// a straight road shows a ridge along it, a wrong local optimum a second peak.
struct CostLandscape {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  CostLandscapeOptions options;
  int size = 0;                  // cells per side: 2 * round(halfExtent / step) + 1
  std::vector<double> scores;    // size * size, row-major, row = y offset, col = x offset (ascending)
  std::vector<double> yawScores; // one per yaw offset (ascending)
  double offset(int index) const { return (index - size / 2) * options.step; }
  double at(int row, int col) const { return scores[size_t(row) * size + col]; }
  int yawCount() const { return int(yawScores.size()); }
  double yawOffsetDeg(int index) const { return (index - yawCount() / 2) * options.yawStepDeg; }
};

CostLandscape costLandscape(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& center,
                            const CostLandscapeOptions& options = {});

// The landscape the matcher's finest level sees: the map's grid of the smallest of match.cellSizes,
// scored with match's outlier ratio (options.score's is replaced by it).
CostLandscape matchLandscape(const HdMap& map, const MatchOptions& match, std::span<const Eigen::Vector2d> points,
                             const Eigen::Vector3d& center, CostLandscapeOptions options = {});

}  // namespace hdprior
