// The outline of a missing surface's cells.
#include "engine/changes/missing_surface.h"

#include <gtest/gtest.h>

namespace hdprior {
namespace {

TEST(MissingSurface, TheOutlineOfAnLShapeFollowsTheCellEdgesCounterClockwise) {
  GridGeometry g;
  g.resolution = 1.0;
  g.cols = g.rows = 4;
  // Cells (0,0), (1,0), (2,0) and (0,1), (0,2): an L.
  const std::vector<int> cells = {0, 1, 2, 4, 8};
  const std::vector<Eigen::Vector2d> outline = cellOutline(g, cells);
  ASSERT_EQ(outline.size(), 6u);
  double area2 = 0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d& p = outline[i];
    const Eigen::Vector2d& q = outline[(i + 1) % outline.size()];
    area2 += p.x() * q.y() - q.x() * p.y();
  }
  EXPECT_DOUBLE_EQ(area2 / 2, 5.0);
}

}  // namespace
}  // namespace hdprior
