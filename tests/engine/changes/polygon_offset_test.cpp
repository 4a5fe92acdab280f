// A polygon the map holds shifted by about a metre: no single edge of it is off by more than the
// tolerance, but all of them agree on one translation and none with the map.
#include "engine/changes/polygon_offset.h"

#include <gtest/gtest.h>

#include "engine/changes/map_change_report.h"
#include "engine/changes/synthetic_street.h"
#include "engine/map/synthetic_maps.h"

namespace hdprior {
namespace {

// A square of road, |x| and |y| below 8 m, with kerbs all round.
test::GroundPoint square(double x, double y) {
  const double a = std::max(std::abs(x), std::abs(y));
  return {a < 8.0, a < 8.0, a > 7.8 && a < 8.0};
}

std::vector<EdgeOffset> squareSeenFrom(const Eigen::Vector2d& shift, int perSide) {
  std::vector<EdgeOffset> out;
  for (const Eigen::Vector2d n : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)})
    for (int i = 0; i < perSide; ++i) out.push_back({8.0 * n, n, -n.dot(shift)});
  return out;
}

TEST(PolygonOffset, OneTranslationThatAllEdgesShareIsFound) {
  const std::optional<PolygonOffset> p = polygonOffset(squareSeenFrom({0.9, -0.6}, 5), {}, ChangeOptions{});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->translation.x(), -0.9, 1e-3);  // the ridge that keeps an unseen direction at zero
  EXPECT_NEAR(p->translation.y(), 0.6, 1e-3);
  EXPECT_EQ(p->samples, 20);
  EXPECT_DOUBLE_EQ(p->fitShare, 1.0);
  EXPECT_DOUBLE_EQ(p->mapShare, 0.0);
}

TEST(PolygonOffset, EdgesThatAgreeWithTheMapOrDisagreeAmongThemselvesAreNoOffset) {
  const ChangeOptions o;
  EXPECT_FALSE(polygonOffset(squareSeenFrom({0.2, 0.1}, 5), {}, o)) << "within the band of the map";
  EXPECT_FALSE(polygonOffset(squareSeenFrom({1.5, 0.0}, 2), {}, o)) << "too few samples";
  // One side 1.2 m off, the three others on the map: a kerb moved, not a polygon shifted.
  std::vector<EdgeOffset> oneSide = squareSeenFrom({0.0, 0.0}, 5);
  for (int i = 0; i < 5; ++i) oneSide[size_t(i)].offset = -1.2;
  EXPECT_FALSE(polygonOffset(oneSide, {}, o));
  // Edges scattered a metre either way: no translation puts most of them in place.
  std::vector<EdgeOffset> scattered = squareSeenFrom({0.0, 0.0}, 6);
  for (size_t i = 0; i < scattered.size(); ++i) scattered[i].offset = i % 2 ? 1.1 : -1.1;
  EXPECT_FALSE(polygonOffset(scattered, {}, o));
}

TEST(PolygonOffset, WhereThePolygonsAroundFollowTheSameTranslationThePosesAreOff) {
  const ChangeOptions o;
  const Eigen::Vector2d shift(1.2, 0.0);
  std::vector<EdgeOffset> around = squareSeenFrom(shift, 5);
  for (EdgeOffset& e : around) e.point += Eigen::Vector2d(0.0, 17.0);  // the next block, 1 m from the square's edge
  EXPECT_FALSE(polygonOffset(squareSeenFrom(shift, 5), around, o));
  for (EdgeOffset& e : around) e.offset = 0.0;
  EXPECT_TRUE(polygonOffset(squareSeenFrom(shift, 5), around, o)) << "the block around on its map: the square moved";
  for (EdgeOffset& e : around) e.point += Eigen::Vector2d(0.0, 100.0), e.offset = -e.normal.dot(shift);
  EXPECT_TRUE(polygonOffset(squareSeenFrom(shift, 5), around, o)) << "too far away to tell";
}

TEST(PolygonOffset, ASquareMappedAMetreOffIsContradictedAllRound) {
  const Eigen::Vector2d shift(0.9, 0.7);  // each side's normal part stays below the 1.25 m tolerance
  const HdMap map = test::streetMap({test::rectangle(-8 + shift.x(), -8 + shift.y(), 8 + shift.x(), 8 + shift.y())});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(square), map, ChangeOptions{});
  int contradicted = 0;
  for (const BoundaryStretch& s : r.stretches) {
    if (s.verdict != MapVerdict::Contradicted) continue;
    ++contradicted;
    EXPECT_EQ(s.evidence, "polygon_offset") << "stretch " << s.index;
    EXPECT_NEAR(s.polygonShift.x(), -shift.x(), 0.3);
    EXPECT_NEAR(s.polygonShift.y(), -shift.y(), 0.3);
    EXPECT_GT(s.confidence, 0.5);
  }
  EXPECT_GE(contradicted, 4);
  ASSERT_EQ(r.drivableAreas.size(), 1u);
  EXPECT_EQ(r.drivableAreas[0].verdict, MapVerdict::Contradicted);
}

TEST(PolygonOffset, TheSameSquareMappedInPlaceIsConsistent) {
  const HdMap map = test::streetMap({test::rectangle(-8, -8, 8, 8)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(square), map, ChangeOptions{});
  ASSERT_EQ(r.drivableAreas.size(), 1u);
  EXPECT_EQ(r.drivableAreas[0].verdict, MapVerdict::Consistent);
  for (const BoundaryStretch& s : r.stretches) EXPECT_NE(s.evidence, "polygon_offset") << "stretch " << s.index;
}

TEST(PolygonOffset, AStreetWithOneKerbAMetreOffIsNoPolygonOffset) {
  // The north boundary drawn 1 m beyond its kerb, the south one on it: below the tolerance, and
  // no one translation explains both sides.
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 6)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, ChangeOptions{});
  for (const BoundaryStretch& s : r.stretches) EXPECT_NE(s.verdict, MapVerdict::Contradicted) << "stretch " << s.index;
}

}  // namespace
}  // namespace hdprior
