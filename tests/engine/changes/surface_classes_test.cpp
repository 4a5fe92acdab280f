// Road grows from the road walk over the same surface; what it stops at is not road.
#include "engine/changes/surface_classes.h"

#include <gtest/gtest.h>

#include "engine/changes/synthetic_street.h"

namespace hdprior {
namespace {

TEST(SurfaceClasses, RoadGrowsFromTheWalkToTheKerbAndTheSidewalkBesideItIsNotRoad) {
  SurfaceEvidence e = test::streetEvidence(test::straightStreet);
  classifySurface(e, ChangeOptions{});
  EXPECT_EQ(e.surfaceAt({0.0, 0.0}), Surface::Road);
  EXPECT_EQ(e.surfaceAt({5.0, 4.6}), Surface::Road);  // grown beyond the walk, up to the kerb
  EXPECT_EQ(e.surfaceAt({5.0, -4.6}), Surface::Road);
  EXPECT_EQ(e.surfaceAt({5.0, 5.4}), Surface::NotRoad);
  EXPECT_EQ(e.surfaceAt({5.0, 9.0}), Surface::NotRoad);
  EXPECT_EQ(e.surfaceAt({5.0, 19.0}), Surface::Unknown);  // farther than the reach beyond the road
  EXPECT_EQ(e.surfaceAt({5.0, 23.0}), Surface::Unknown);  // not seen
}

}  // namespace
}  // namespace hdprior
