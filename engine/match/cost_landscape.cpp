#include "engine/match/cost_landscape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/error.h"
#include "engine/geom/angles.h"
#include "engine/map/hd_map.h"
#include "engine/map/ndt_grid.h"
#include "engine/odom/parallel_for.h"

namespace hdprior {
namespace {

void validate(const CostLandscapeOptions& o) {
  if (!(o.step > 0) || !(o.halfExtent >= 0) || o.halfExtent / o.step > 2000)
    throw Error("cost landscape options", "step must be positive and halfExtent / step at most 2000");
  if (!(o.yawStepDeg > 0) || !(o.yawHalfDeg >= 0) || o.yawHalfDeg / o.yawStepDeg > 2000)
    throw Error("cost landscape options", "yawStepDeg must be positive and yawHalfDeg / yawStepDeg at most 2000");
}

}  // namespace

CostLandscape costLandscape(const NdtGrid& grid, std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& center,
                            const CostLandscapeOptions& options) {
  validate(options);
  CostLandscape l;
  l.center = center;
  l.options = options;
  l.size = 2 * int(std::lround(options.halfExtent / options.step)) + 1;
  l.scores.resize(size_t(l.size) * l.size);
  const auto score = [&](const Eigen::Vector3d& pose) {
    return scoreNdt(grid, points, pose, options.score, NdtDerivatives::None).score;
  };
  // Each row is written by its own index: the same result for any thread count.
  parallelFor(
      size_t(l.size), options.threads,
      [&](size_t begin, size_t end) {
        for (size_t row = begin; row < end; ++row) {
          for (int col = 0; col < l.size; ++col)
            l.scores[row * l.size + col] = score(center + Eigen::Vector3d(l.offset(col), l.offset(int(row)), 0.0));
        }
      },
      8);
  const int yawHalf = int(std::lround(options.yawHalfDeg / options.yawStepDeg));
  for (int i = -yawHalf; i <= yawHalf; ++i)
    l.yawScores.push_back(score(center + Eigen::Vector3d(0.0, 0.0, i * options.yawStepDeg * kDegree)));
  return l;
}

CostLandscape matchLandscape(const HdMap& map, const MatchOptions& match, std::span<const Eigen::Vector2d> points,
                             const Eigen::Vector3d& center, CostLandscapeOptions options) {
  if (match.cellSizes.empty()) throw Error("match options", "cellSizes is empty");
  options.score = {.outlierRatio = match.outlierRatio};
  const double finest = *std::min_element(match.cellSizes.begin(), match.cellSizes.end());
  return costLandscape(map.ndtGrid(finest), points, center, options);
}

}  // namespace hdprior
