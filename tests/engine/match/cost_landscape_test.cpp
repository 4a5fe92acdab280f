// The cost landscape on synthetic maps: its maximum at the matcher's result at an intersection,
// a ridge along a corridor (and no ridge at the intersection), and its values are the NDT score.
#include "engine/geom/angles.h"
#include "engine/match/cost_landscape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "../map/synthetic_maps.h"
#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/map/drivable_raster.h"
#include "engine/map/hd_map.h"
#include "engine/map/ndt_grid.h"
#include "engine/match/map_matcher.h"
#include "matcher_map.h"
#include "ring_road_points.h"

namespace hdprior {
namespace {

HdMap intersection() { return test::matcherMap(test::mapOf({test::rectangle(-100, -5, 100, 5), test::rectangle(-6, -100, 6, 100)})); }
HdMap corridor() { return test::matcherMap(test::mapOf({test::rectangle(-150, -5, 150, 5)})); }

// Road points as a thinned sweep gives them: a 0.4 m lattice within 30 m of the vehicle (at
// `truth`), kept where it lands on the drivable area; in the vehicle's frame.
std::vector<Eigen::Vector2d> latticeRoadPoints(const DrivableRaster& drivable, const Eigen::Vector3d& truth) {
  std::vector<Eigen::Vector2d> points;
  for (double x = -30.0; x <= 30.0; x += 0.4) {
    for (double y = -30.0; y <= 30.0; y += 0.4) {
      const Eigen::Vector2d p(x, y);
      if (p.norm() <= 30.0 && drivable.contains(Eigen::Rotation2Dd(truth.z()) * p + truth.head<2>())) points.push_back(p);
    }
  }
  return points;
}

const NdtGrid& finestGrid(const HdMap& map) { return map.ndtGrids().back(); }  // coarse to fine

// The score's range along the centre row (city x, the corridor's axis) over its range along the
// centre column (city y, across).
double alongOverAcross(const CostLandscape& l) {
  const int c = l.size / 2;
  double alongMin = 1e300, alongMax = -1e300, acrossMin = 1e300, acrossMax = -1e300;
  for (int i = 0; i < l.size; ++i) {
    alongMin = std::min(alongMin, l.at(c, i));
    alongMax = std::max(alongMax, l.at(c, i));
    acrossMin = std::min(acrossMin, l.at(i, c));
    acrossMax = std::max(acrossMax, l.at(i, c));
  }
  return (alongMax - alongMin) / (acrossMax - acrossMin);
}

TEST(CostLandscape, MaximumLiesAtTheMatchersResultAtAnIntersection) {
  const HdMap map = intersection();
  const Eigen::Vector3d truth(2.0, -1.0, 0.3);
  const std::vector<Eigen::Vector2d> points = latticeRoadPoints(map.drivable(), truth);
  MatchOptions mo;
  mo.timeBudgetMs = 1e6;
  MapMatcher matcher(map, mo);
  const MatchResult r = matcher.match(points, offsetPose(truth, {1.0, -1.0, 2.0 * kDegree}));
  ASSERT_EQ(r.status, MatchStatus::Accepted) << r.reason;
  // Centred off the result, so the maximum is not at the centre by construction.
  const Eigen::Vector3d center = r.estimate + Eigen::Vector3d(0.83, -0.64, 0.0);
  const CostLandscape l = matchLandscape(map, MatchOptions{}, points, center);
  ASSERT_EQ(l.size, 61);
  ASSERT_EQ(l.scores.size(), size_t(61 * 61));
  const auto best = std::max_element(l.scores.begin(), l.scores.end()) - l.scores.begin();
  const Eigen::Vector2d at = center.head<2>() + Eigen::Vector2d(l.offset(int(best % l.size)), l.offset(int(best / l.size)));
  EXPECT_LT((at - r.estimate.head<2>()).cwiseAbs().maxCoeff(), l.options.step + 1e-9)
      << "maximum at " << at.transpose() << ", match at " << r.estimate.head<2>().transpose();
  // The yaw profile around the result peaks at its middle (within one step).
  const CostLandscape y = matchLandscape(map, MatchOptions{}, points, r.estimate);
  ASSERT_EQ(y.yawCount(), 41);
  const int bestYaw = int(std::max_element(y.yawScores.begin(), y.yawScores.end()) - y.yawScores.begin());
  EXPECT_LE(std::abs(y.yawOffsetDeg(bestYaw)), y.options.yawStepDeg + 1e-9);
  // An intersection constrains both directions: no ridge.
  EXPECT_GT(alongOverAcross(y), 0.1);
}

TEST(CostLandscape, IsARidgeAlongACorridor) {
  const HdMap map = corridor();
  const Eigen::Vector3d truth(3.0, 1.5, 0.0);
  const std::vector<Eigen::Vector2d> points = latticeRoadPoints(map.drivable(), truth);
  const CostLandscape l = matchLandscape(map, MatchOptions{}, points, truth);
  const double ratio = alongOverAcross(l);
  EXPECT_LT(ratio, 0.1) << "the score varies along the corridor by " << ratio << " of its variation across it";
}

TEST(CostLandscape, ValuesAreTheNdtScoreAtEachOffset) {
  const HdMap map = intersection();
  const Eigen::Vector3d pose(2.0, -1.0, 0.3);
  const std::vector<Eigen::Vector2d> points = test::ringRoadPoints(map.drivable(), pose);
  CostLandscapeOptions o;
  o.score = {.outlierRatio = 0.55};
  o.halfExtent = 1.0;
  o.step = 0.5;
  o.yawHalfDeg = 2.0;
  o.yawStepDeg = 1.0;
  const CostLandscape l = costLandscape(finestGrid(map), points, pose, o);
  ASSERT_EQ(l.size, 5);
  ASSERT_EQ(l.yawCount(), 5);
  const auto score = [&](const Eigen::Vector3d& p) { return scoreNdt(finestGrid(map), points, p, o.score, NdtDerivatives::None).score; };
  EXPECT_DOUBLE_EQ(l.at(0, 4), score(pose + Eigen::Vector3d(1.0, -1.0, 0.0)));
  EXPECT_DOUBLE_EQ(l.at(3, 1), score(pose + Eigen::Vector3d(-0.5, 0.5, 0.0)));
  EXPECT_DOUBLE_EQ(l.yawScores[0], score(pose + Eigen::Vector3d(0.0, 0.0, -2.0 * kDegree)));
  // Rows are written by index: the same for any thread count.
  CostLandscapeOptions fine = o;
  fine.step = 0.1;
  const CostLandscape two = costLandscape(finestGrid(map), points, pose, fine);
  fine.threads = 1;
  EXPECT_EQ(costLandscape(finestGrid(map), points, pose, fine).scores, two.scores);
  o.step = 0.0;
  EXPECT_THROW(costLandscape(finestGrid(map), points, pose, o), Error);
}

}  // namespace
}  // namespace hdprior
