// The change check on a made-up street: what agrees with the map is consistent, a boundary
// drawn in the wrong place is contradicted by as much as it is off (inside only where the walk saw
// the kerb), and road the map lacks is a missing surface.
#include "engine/changes/map_change_report.h"

#include <gtest/gtest.h>

#include "engine/changes/synthetic_street.h"
#include "engine/map/synthetic_maps.h"

namespace hdprior {
namespace {

// The stretches of one polygon with a verdict.
std::vector<BoundaryStretch> judged(const MapChangeReport& r, int64_t id) {
  std::vector<BoundaryStretch> out;
  for (const BoundaryStretch& s : r.stretches)
    if (s.areaId == id && s.verdict != MapVerdict::Unobserved) out.push_back(s);
  return out;
}

TEST(MapChangeReport, AMapThatAgreesWithTheKerbsIsConsistent) {
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 5)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, ChangeOptions{});
  const std::vector<BoundaryStretch> seen = judged(r, 1);
  ASSERT_GE(seen.size(), 6u);  // 40 m of each side
  for (const BoundaryStretch& s : seen) {
    EXPECT_EQ(s.verdict, MapVerdict::Consistent) << "stretch " << s.index;
    EXPECT_LT(std::abs(s.offset), 0.5);
  }
  ASSERT_EQ(r.drivableAreas.size(), 1u);
  EXPECT_EQ(r.drivableAreas[0].verdict, MapVerdict::Consistent);
  EXPECT_TRUE(r.missing.empty());
}

TEST(MapChangeReport, ABoundaryDrawnTwoMetresInsideTheKerbIsContradictedByTwoMetres) {
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 3)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, ChangeOptions{});
  int contradicted = 0, consistent = 0;
  for (const BoundaryStretch& s : judged(r, 1)) {
    const double y = s.line.front().y();
    if (std::abs(y - 3.0) < 0.01) {
      ++contradicted;
      EXPECT_EQ(s.verdict, MapVerdict::Contradicted) << "stretch " << s.index;
      EXPECT_NEAR(s.offset, 2.0, 0.3);
      EXPECT_EQ(s.evidence, "road_beyond_boundary");
      EXPECT_GT(s.confidence, 0.5);
    } else if (std::abs(y + 5.0) < 0.01) {
      ++consistent;
      EXPECT_EQ(s.verdict, MapVerdict::Consistent) << "stretch " << s.index;
    }
  }
  EXPECT_GE(contradicted, 3);
  EXPECT_GE(consistent, 3);
  EXPECT_EQ(r.drivableAreas[0].verdict, MapVerdict::Contradicted);
  EXPECT_TRUE(r.missing.empty()) << "2 m is a boundary drawn wrong, not a missing surface";
}

TEST(MapChangeReport, AnEdgeSeenOnlyFromAfarContradictsNothing) {
  // The sweep is taken at the origin: with edges read from 8 m at most, the stretches of the
  // wrong boundary farther along the street say nothing; the one beside the lidar still contradicts.
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 3)});
  ChangeOptions options;
  options.edgeRange = 8.0;
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, options);
  int near = 0, far = 0;
  for (const BoundaryStretch& s : r.stretches) {
    if (s.areaId != 1 || std::abs(s.line.front().y() - 3.0) > 0.01) continue;
    const double closest = std::min(std::abs(s.line.front().x()), std::abs(s.line.back().x()));
    const bool spansOrigin = s.line.front().x() * s.line.back().x() <= 0.0;
    if (spansOrigin || closest < 4.0) {
      ++near;
      EXPECT_EQ(s.verdict, MapVerdict::Contradicted) << "stretch " << s.index;
      EXPECT_LE(s.nearestView, 8.0);
    } else if (closest > 8.0 && closest < 19.0) {
      ++far;
      EXPECT_NE(s.verdict, MapVerdict::Contradicted) << "stretch " << s.index;
    }
  }
  EXPECT_GE(near, 1);
  EXPECT_GE(far, 2);
}

TEST(MapChangeReport, ABoundaryDrawnTwoMetresOutsideTheKerbIsContradictedWhereTheWalkSawTheKerb) {
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 7)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, ChangeOptions{});
  int contradicted = 0;
  for (const BoundaryStretch& s : judged(r, 1))
    if (std::abs(s.line.front().y() - 7.0) < 0.01) {
      ++contradicted;
      EXPECT_EQ(s.verdict, MapVerdict::Contradicted) << "stretch " << s.index;
      EXPECT_NEAR(s.offset, -2.0, 0.3);
      EXPECT_EQ(s.evidence, "kerb_inside");
    }
  EXPECT_GE(contradicted, 2);  // those whose kerb the lidar saw within ChangeOptions::edgeRange (the sweep is at the origin)
}

TEST(MapChangeReport, AStretchWhoseFewSamplesMostlyContradictItIsUnobservedNotConsistent) {
  // The north kerb steps 2 m out over 4 m of one stretch (x in [2, 6)): too few samples to
  // contradict the map, too many to agree with it.
  auto world = [](double x, double y) {
    test::GroundPoint g = test::straightStreet(x, y);
    if (x >= 2.0 && x < 6.0 && y >= 4.8 && y < 7.0) g = {true, true, y > 6.8};
    return g;
  };
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(world), test::streetMap({test::rectangle(-100, -5, 100, 5)}),
                                            ChangeOptions{});
  bool seen = false;
  for (const BoundaryStretch& s : r.stretches) {
    if (s.areaId != 1 || std::abs(s.line.front().y() - 5.0) > 0.01) continue;
    const double lo = std::min(s.line.front().x(), s.line.back().x()), hi = std::max(s.line.front().x(), s.line.back().x());
    if (lo > 2.0 || hi < 6.0) continue;
    seen = true;
    EXPECT_GT(s.contradicted, 0);
    EXPECT_LT(s.contradicted, ChangeOptions{}.minSamples);
    EXPECT_GE(double(s.contradicted), ChangeOptions{}.contradictedShare * s.observed);
    EXPECT_EQ(s.verdict, MapVerdict::Unobserved);
    EXPECT_TRUE(s.undecided());  // the changes layer draws it apart from the stretches nothing was seen of
    EXPECT_EQ(s.evidence, "road_beyond_boundary");
    EXPECT_NEAR(s.offset, 2.0, 0.3);
  }
  EXPECT_TRUE(seen);
  for (const BoundaryStretch& s : r.stretches) {
    if (s.verdict != MapVerdict::Unobserved || s.contradicted == 0) {
      EXPECT_FALSE(s.undecided()) << "stretch " << s.index;
    }
  }
}

TEST(MapChangeReport, WhereTheWalkStoppedShortOfTheBoundaryWithoutAKerbNothingIsRead) {
  // The walk ends 2 m inside the map's boundary with no kerb there (a parked car, a gap): no verdict.
  auto world = [](double x, double y) {
    test::GroundPoint g = test::straightStreet(x, y);
    if (y > 3.0) g.walked = g.kerb = false;
    return g;
  };
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(world), test::streetMap({test::rectangle(-100, -5, 100, 5)}),
                                            ChangeOptions{});
  for (const BoundaryStretch& s : judged(r, 1)) EXPECT_NE(s.verdict, MapVerdict::Contradicted) << "stretch " << s.index;
}

// The stretches across the gap between the street's two polygons (x = 0 and x = `gap`), with a verdict.
std::vector<BoundaryStretch> acrossTheGap(double gap) {
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 0, 5), test::rectangle(gap, -5, 100, 5)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, ChangeOptions{});
  std::vector<BoundaryStretch> out;
  for (int64_t id : {1, 2})
    for (const BoundaryStretch& s : judged(r, id))
      if (std::abs(s.line.front().x() - (id == 1 ? 0.0 : gap)) < 0.01 && std::abs(s.line.back().x() - s.line.front().x()) < 0.01)
        out.push_back(s);
  return out;
}

TEST(MapChangeReport, RoadAcrossAGapBetweenTwoPolygonsContradictsBothSides) {
  // A narrowed polygon leaves a gap to its neighbour: the road goes on across it.
  const std::vector<BoundaryStretch> wide = acrossTheGap(2.5);
  ASSERT_EQ(wide.size(), 2u);
  for (const BoundaryStretch& s : wide) {
    EXPECT_EQ(s.verdict, MapVerdict::Contradicted) << "area " << s.areaId;
    EXPECT_EQ(s.evidence, "road_across_gap");
    EXPECT_NEAR(s.offset, 2.5, 0.3);
  }
  // A gap within the tolerance is the map's error.
  const std::vector<BoundaryStretch> narrow = acrossTheGap(1.0);
  ASSERT_EQ(narrow.size(), 2u);
  for (const BoundaryStretch& s : narrow) EXPECT_EQ(s.verdict, MapVerdict::Consistent) << "area " << s.areaId;
}

TEST(MapChangeReport, RoadTheMapLacksIsAMissingSurfaceWithItsOutline) {
  // A side street 6 m wide leaves northwards at x in [-3, 3]; the map has only the street.
  auto world = [](double x, double y) {
    test::GroundPoint g = test::straightStreet(x, y);
    if (y > 0 && std::abs(x) < 3.0) g = {true, true, false};
    return g;
  };
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 5)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(world), map, ChangeOptions{});
  ASSERT_EQ(r.missing.size(), 1u);
  const MissingSurface& m = r.missing[0];
  // Seen from y = 6 (1 m gap) to 20: 6 m x 14 m.
  EXPECT_NEAR(m.area, 84.0, 12.0);
  EXPECT_GT(m.depth, 8.0);  // the distance field reaches 10 m beyond the polygons (the raster margin)
  double minX = 1e9, maxX = -1e9, minY = 1e9;
  for (const Eigen::Vector2d& p : m.outline) {
    minX = std::min(minX, p.x()), maxX = std::max(maxX, p.x()), minY = std::min(minY, p.y());
  }
  EXPECT_NEAR(minX, -3.0, 0.5);
  EXPECT_NEAR(maxX, 3.0, 0.5);
  EXPECT_NEAR(minY, 6.0, 0.5);
  EXPECT_GT(m.confidence, 0.9);
  // The street's boundary across the side street's mouth is open road, not a kerb in the wrong place.
  for (const BoundaryStretch& s : judged(r, 1)) {
    if (std::abs(s.line.front().y() - 5.0) < 0.01) {
      EXPECT_NE(s.evidence, "kerb_inside");
    }
  }
}

}  // namespace
}  // namespace hdprior
