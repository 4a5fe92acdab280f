// A cell is road where the road walk reached most of its points, not road where it saw them and
// reached none, unknown where it saw too little.
#include "engine/changes/surface_classes.h"

#include <gtest/gtest.h>

#include "engine/changes/synthetic_street.h"

namespace hdprior {
namespace {

TEST(SurfaceClasses, TheWalkedStreetIsRoadTheSidewalkIsNotAndTheUnseenIsUnknown) {
  auto world = [](double x, double y) {
    test::GroundPoint g = test::straightStreet(x, y);
    if (x > 10 && x < 10.5 && y > 0 && y < 1) g.walked = (int(y * 10) % 3) == 0;  // a third of them walked
    return g;
  };
  SurfaceEvidence e = test::streetEvidence(world);
  classifySurface(e, ChangeOptions{});
  EXPECT_EQ(e.surfaceAt({0.0, 0.0}), Surface::Road);
  EXPECT_EQ(e.surfaceAt({5.0, 4.6}), Surface::Road);
  EXPECT_EQ(e.surfaceAt({5.0, 5.4}), Surface::NotRoad);
  EXPECT_EQ(e.surfaceAt({5.0, 19.0}), Surface::NotRoad);
  EXPECT_EQ(e.surfaceAt({5.0, 23.0}), Surface::Unknown);  // not seen
  EXPECT_EQ(e.surfaceAt({10.25, 0.25}), Surface::Unknown);  // walked in part
}

}  // namespace
}  // namespace hdprior
