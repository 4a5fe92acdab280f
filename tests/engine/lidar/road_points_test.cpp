// Ground segmentation and road points on a synthetic street with curbs, sidewalks, walls
// and a car, scanned by a simulated 32-ring lidar.
#include "engine/lidar/road_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "engine/error.h"
#include "engine/lidar/ground_segmentation.h"
#include "synthetic_scan.h"

namespace hdprior {
namespace {

using test::Surface;

struct Labelled {
  std::vector<Eigen::Vector3d> points;
  std::vector<uint8_t> rings;
  std::vector<Surface> truth;
};

Labelled scan(const test::Street& street) {
  Labelled l;
  for (const test::ScanPoint& p : test::scanStreet(street)) {
    l.points.push_back(p.p);
    l.rings.push_back(p.ring);
    l.truth.push_back(p.surface);
  }
  return l;
}

// Share of the points of each true surface (within the options' ranges) given the flag.
std::map<Surface, double> flaggedShare(const Labelled& l, const std::vector<uint8_t>& flags, double minRange,
                                       double maxRange) {
  std::map<Surface, std::pair<double, double>> counts;
  for (size_t i = 0; i < l.points.size(); ++i) {
    const double r = l.points[i].head<2>().norm();
    if (r < minRange || r > maxRange) continue;
    counts[l.truth[i]].first += flags[i];
    counts[l.truth[i]].second += 1;
  }
  std::map<Surface, double> share;
  for (const auto& [s, c] : counts) share[s] = c.first / c.second;
  return share;
}

TEST(GroundSegmentation, FindsRoadAndSidewalkButNotWallsOrCars) {
  const Labelled l = scan({});
  const std::vector<uint8_t> ground = segmentGround(l.points);
  const auto share = flaggedShare(l, ground, 3.0, 40.0);
  EXPECT_GT(share.at(Surface::Road), 0.97);
  EXPECT_GT(share.at(Surface::Sidewalk), 0.85);
  EXPECT_LT(share.at(Surface::Wall), 0.04);  // the bottom of a wall lies within planeDistance of the sidewalk
  EXPECT_LT(share.at(Surface::Car), 0.02);
}

TEST(RoadPoints, StopAtCurbsAndStepOverCars) {
  const Labelled l = scan({});
  const std::vector<uint8_t> ground = segmentGround(l.points);
  const std::vector<uint8_t> road = extractRoadPoints(l.points, l.rings, ground);
  const auto share = flaggedShare(l, road, 3.0, 40.0);
  EXPECT_GT(share.at(Surface::Road), 0.95);
  EXPECT_LT(share.at(Surface::Sidewalk), 0.01);
  EXPECT_LT(share.at(Surface::Wall), 0.001);
  EXPECT_LT(share.at(Surface::Car), 0.001);
  // Behind the car (the road seen past it on the same rings) is still road.
  size_t behind = 0, behindRoad = 0;
  for (size_t i = 0; i < l.points.size(); ++i) {
    if (l.truth[i] == Surface::Road && l.points[i].x() > 10.5 && l.points[i].x() < 40.0 && l.points[i].y() < -1.2 && l.points[i].y() > -4.9) {
      ++behind;
      behindRoad += road[i];
    }
  }
  ASSERT_GT(behind, 20u);
  EXPECT_GT(double(behindRoad) / double(behind), 0.9);
}

TEST(RoadPoints, LowCurbIsStillACurb) {
  test::Street street;
  street.curb = 0.10;
  const Labelled l = scan(street);
  const std::vector<uint8_t> road = extractRoadPoints(l.points, l.rings, segmentGround(l.points));
  EXPECT_LT(flaggedShare(l, road, 3.0, 40.0).at(Surface::Sidewalk), 0.02);
}

// A car parked at the kerb, its body down to the road: the rings climb its side through points
// close enough to the road to be ground, then meet the step of its higher side. Neither that
// step nor one hidden behind the car is a curb; the kerbs beside it still are.
TEST(RoadPoints, AParkedCarsSideIsNoCurb) {
  test::Street street;
  street.carNearY = -(street.halfWidth - 0.2 - 1.8);
  street.carClearance = 0.0;
  const Labelled l = scan(street);
  const std::vector<uint8_t> road = extractRoadPoints(l.points, l.rings, segmentGround(l.points));
  size_t atCar = 0, atKerb = 0;
  for (size_t i = 0; i < l.points.size(); ++i) {
    if (road[i] != kCurbPoint) continue;
    const Eigen::Vector3d& p = l.points[i];
    if (p.x() > 5.0 && p.x() < 11.0 && std::abs(p.y() - street.carNearY) < 0.8) ++atCar;
    if (std::abs(std::abs(p.y()) - street.halfWidth) < 0.5) ++atKerb;
  }
  EXPECT_EQ(atCar, 0u);  // 4 before the rule
  EXPECT_GT(atKerb, 40u);
}

TEST(RoadPoints, LaneSeedsEndAtTheKerbAcrossTheRoad) {
  // Driving towards a T-junction's far side 18 m ahead: beyond its kerb the x axis runs on raised
  // ground within the seed tolerance (0.12 m + 0.01 m per metre), so seeds there walk whole rings
  // on the sidewalk (over 5 % of it was road before); lane seeds end at the kerb.
  test::Street street;
  street.endAt = 18.0;
  street.car = false;
  const Labelled l = scan(street);
  const auto share = flaggedShare(l, extractRoadPoints(l.points, l.rings, segmentGround(l.points)), 3.0, 40.0);
  EXPECT_LT(share.at(Surface::Sidewalk), 0.01);
  EXPECT_GT(share.at(Surface::Road), 0.95);
}

// One ring 10 m out over a road whose low kerb hides behind its gutter: the camber (2.9 %) comes down
// to a gutter 4 cm deep at the edge (|y| = 5 m), a 4.5 cm lip brings the surface back to 0.5 cm above
// the camber's line, and the verge rises at 1.1 %. Every point is ground.
struct RingProfile {
  std::vector<Eigen::Vector3d> points;
  std::vector<uint8_t> rings, ground;
};

RingProfile gutterRing() {
  constexpr double kRange = 10.0, kEdge = 5.0, kRoadZ = -0.32;
  RingProfile r;
  for (double az = -1.2; az <= 1.2; az += 0.01) {
    const double y = kRange * std::sin(az), ay = std::abs(y);
    double z = kRoadZ - 0.029 * std::max(0.0, std::min(ay, kEdge) - 1.0);
    if (ay <= kEdge && ay > kEdge - 0.4) z -= 0.04 * (ay - (kEdge - 0.4)) / 0.4;
    if (ay > kEdge) z += 0.005 + 0.011 * (ay - kEdge);
    r.points.emplace_back(kRange * std::cos(az), y, z);
  }
  r.rings.assign(r.points.size(), 0);
  r.ground.assign(r.points.size(), 1);
  return r;
}

TEST(RoadPoints, AKerbBehindItsGutterEndsTheRoadAtTheGutter) {
  const RingProfile r = gutterRing();
  RoadPointOptions withoutGutter;
  withoutGutter.gutterRise = 0.0;
  const std::vector<uint8_t> before = extractRoadPoints(r.points, r.rings, r.ground, withoutGutter);
  const std::vector<uint8_t> after = extractRoadPoints(r.points, r.rings, r.ground);
  size_t sidewalk = 0, sidewalkBefore = 0, sidewalkAfter = 0, road = 0, roadAfter = 0;
  std::vector<double> curbs;
  for (size_t i = 0; i < r.points.size(); ++i) {
    const double ay = std::abs(r.points[i].y());
    if (ay > 5.0) {
      ++sidewalk;
      sidewalkBefore += before[i] != 0;
      sidewalkAfter += after[i] != 0;
    } else {
      ++road;
      roadAfter += after[i] != 0;
    }
    if (after[i] == kCurbPoint) curbs.push_back(ay);
  }
  EXPECT_GT(double(sidewalkBefore) / double(sidewalk), 0.03);  // the step test alone lets part through
  EXPECT_EQ(sidewalkAfter, 0u);
  EXPECT_GT(double(roadAfter) / double(road), 0.95);
  ASSERT_EQ(curbs.size(), 2u);  // one on each side, at the gutter
  for (double y : curbs) EXPECT_NEAR(y, 5.0, 0.3);
}

TEST(RoadPoints, SeedsStayUnderTheVehiclesOwnWidth) {
  // A narrow street driven 0.3 m from each kerb (7 cm: below the lane's 8 cm step, above the
  // walk's 5 cm): seeds out to 1.5 m lie on the sidewalks and walk them as road.
  test::Street street;
  street.halfWidth = 1.3;
  street.curb = 0.07;
  street.car = false;
  const Labelled l = scan(street);
  const std::vector<uint8_t> ground = segmentGround(l.points);
  RoadPointOptions wide, own;
  wide.seedHalfWidth = 1.5;
  own.seedHalfWidth = 1.0;
  const auto fromWide = flaggedShare(l, extractRoadPoints(l.points, l.rings, ground, wide), 3.0, 40.0);
  const auto fromOwn = flaggedShare(l, extractRoadPoints(l.points, l.rings, ground, own), 3.0, 40.0);
  EXPECT_GT(fromWide.at(Surface::Sidewalk), 0.2);
  EXPECT_LT(fromOwn.at(Surface::Sidewalk), 0.02);
  EXPECT_GT(fromOwn.at(Surface::Road), 0.9);
}

TEST(RoadPoints, PlanarPointsThinDeterministically) {
  const std::vector<Eigen::Vector3d> points = {{0.1, 0.1, 0}, {0.3, 0.3, 0}, {1.2, 0.1, 0}, {5, 5, 0}};
  const std::vector<uint8_t> flags = {1, 1, 1, 0};
  const auto thin = planarPoints(points, flags, 1.0);
  ASSERT_EQ(thin.size(), 2u);
  EXPECT_TRUE(thin[0].isApprox(Eigen::Vector2d(0.2, 0.2)));
  EXPECT_TRUE(thin[1].isApprox(Eigen::Vector2d(1.2, 0.1)));
  EXPECT_EQ(planarPoints(points, flags).size(), 3u);
}

TEST(RoadPoints, RejectsMismatchedInputsAndBadOptions) {
  const std::vector<Eigen::Vector3d> points(3, Eigen::Vector3d::Zero());
  const std::vector<uint8_t> two(2, 0), three(3, 0);
  EXPECT_THROW(extractRoadPoints(points, three, two), Error);
  EXPECT_THROW(extractRoadPoints(points, two, three), Error);
  EXPECT_THROW(extractRoadPoints(points, three, three, {.maxStep = 0.0}), Error);
  EXPECT_THROW(segmentGround(points, {.zoneRadii = {8.0}}), Error);
}

}  // namespace
}  // namespace hdprior
