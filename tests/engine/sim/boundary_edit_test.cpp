// Boundary edits on a 40 m x 10 m street-like rectangle: its sides, a side moved inwards whole,
// a tapered stretch of kerb moved in and out.
#include "engine/sim/boundary_edit.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hdprior {
namespace {

const Ring2 kStreet = {{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0}, {40, 10}, {0, 10}};

RingSide bottomSide() {
  for (const RingSide& s : ringSides(kStreet))
    if (s.first == 0) return s;
  return {};
}

TEST(BoundaryEdit, SidesRunFromCornerToCorner) {
  const std::vector<RingSide> sides = ringSides(kStreet);
  ASSERT_EQ(sides.size(), 4u);
  EXPECT_EQ(sides[0].first, 0u);
  EXPECT_EQ(sides[0].last, 4u);
  EXPECT_DOUBLE_EQ(polylineLength2(sideVertices(kStreet, sides[0])), 40.0);
  EXPECT_EQ(sideVertices(kStreet, sides[3]).size(), 2u);  // (0, 10) -> (0, 0)
}

TEST(BoundaryEdit, NarrowingMovesTheWholeSideInwards) {
  const auto edit = narrowSide(kStreet, bottomSide(), 2.0);
  ASSERT_TRUE(edit);
  EXPECT_NEAR(signedArea(edit->ring), 40.0 * 8.0, 1e-9);
  ASSERT_EQ(edit->stretch.size(), 5u);
  for (const Eigen::Vector2d& p : edit->stretch) EXPECT_NEAR(p.y(), 2.0, 1e-9);
  EXPECT_NEAR(edit->stretch.front().x(), 0.0, 1e-9);  // slid along the end edges
  EXPECT_NEAR(edit->stretch.back().x(), 40.0, 1e-9);
  EXPECT_EQ(edit->worldStretch, sideVertices(kStreet, bottomSide()));
  EXPECT_FALSE(narrowSide(kStreet, bottomSide(), 9.0));  // the end edges are too short
}

TEST(BoundaryEdit, AKerbStretchMovesTaperedAndDensified) {
  for (double offset : {-2.0, 2.5}) {
    const auto edit = moveKerbStretch(kStreet, bottomSide(), 12.0, 16.0, offset, 3.0);
    ASSERT_TRUE(edit);
    ASSERT_GE(edit->stretch.size(), 17u);  // a vertex every metre
    EXPECT_NEAR(edit->stretch.front().x(), 12.0, 1e-9);
    EXPECT_NEAR(edit->stretch.back().x(), 28.0, 1e-9);
    EXPECT_NEAR(edit->stretch.front().y(), 0.0, 1e-9);  // tapered to nothing at the ends
    EXPECT_NEAR(edit->stretch.back().y(), 0.0, 1e-9);
    double deepest = 0.0;
    for (const Eigen::Vector2d& p : edit->stretch) {
      if (p.x() >= 15.0 && p.x() <= 25.0) {
        EXPECT_NEAR(p.y(), -offset, 1e-9);  // outwards is -y here
      }
      deepest = std::max(deepest, std::abs(p.y()));
    }
    EXPECT_NEAR(deepest, std::abs(offset), 1e-9);
    EXPECT_NEAR(signedArea(edit->ring) - 400.0, offset * (16.0 - 3.0), 0.5);  // 10 m full, 2 x 3 m tapers at half
    EXPECT_TRUE(isSimpleRing(edit->ring));
  }
  EXPECT_FALSE(moveKerbStretch(kStreet, bottomSide(), 30.0, 16.0, 1.0, 3.0));  // beyond the side's end
}

}  // namespace
}  // namespace hdprior
