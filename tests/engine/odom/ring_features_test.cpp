#include <gtest/gtest.h>

#include <cmath>

#include "engine/odom/ring_features.h"

namespace hdprior {
namespace {

constexpr double kStepDeg = 0.2;

// A ring seen from the origin, sweeping azimuth from `fromDeg` to `toDeg`, hitting `surface(azimuth)`.
template <typename Surface>
std::vector<RingPoint> scanRing(double fromDeg, double toDeg, Surface surface) {
  std::vector<RingPoint> ring;
  for (double a = fromDeg; a <= toDeg + 1e-9; a += kStepDeg) {
    const double rad = a * M_PI / 180;
    const double range = surface(rad);
    ring.push_back({Eigen::Vector3f(float(range * std::cos(rad)), float(range * std::sin(rad)), 0.f), float(rad)});
  }
  return ring;
}

// The wall x = 10 seen over +-20 degrees of azimuth.
double wall(double a) { return 10.0 / std::cos(a); }
// Two walls x = 10 and y = 10 meeting at the corner (10, 10), seen at 45 degrees.
double corner(double a) { return std::min(10.0 / std::cos(a), 10.0 / std::sin(a)); }

int countLabel(const std::vector<FeatureLabel>& labels, FeatureLabel l) {
  return int(std::count(labels.begin(), labels.end(), l));
}

}  // namespace

TEST(RingFeatures, PlaneGivesFlatsPerSector) {
  const auto ring = scanRing(-20, 20, wall);
  const FeatureOptions o;
  const auto labels = labelRing(ring, o);
  EXPECT_EQ(countLabel(labels, FeatureLabel::Flat), o.sectors * o.flatPerSector);
  // Every point with a full neighbourhood is at least less-flat.
  EXPECT_EQ(countLabel(labels, FeatureLabel::Flat) + countLabel(labels, FeatureLabel::LessFlat), int(ring.size()) - 10);
}

bool isPlanePoint(FeatureLabel l) { return l == FeatureLabel::Flat || l == FeatureLabel::LessFlat; }

TEST(RingFeatures, CornerIsNoPlanePoint) {
  const auto ring = scanRing(30, 60, corner);
  FeatureOptions o;
  o.sectors = 1;
  const auto labels = labelRing(ring, o);
  const int cornerIndex = int(std::lround((45.0 - 30.0) / kStepDeg)), k = o.neighbours;
  for (int i = cornerIndex - 1; i <= cornerIndex + 1; ++i) EXPECT_EQ(labels[i], FeatureLabel::None) << i;
  // Beyond the corner's neighbourhood the walls are planes.
  for (int i = k; i < int(labels.size()) - k; ++i) {
    if (std::abs(i - cornerIndex) > k) EXPECT_TRUE(isPlanePoint(labels[i])) << i;
  }
  // It is the edge curvature that keeps the corner out.
  o.edgeCurvature = 10;
  EXPECT_EQ(labelRing(ring, o)[cornerIndex], FeatureLabel::LessFlat);
}

TEST(RingFeatures, OccludedSideOfADepthJumpIsRejected) {
  // A near post (range 5) in front of a far wall (range 20): the wall points beside the post are
  // occluded-edge artefacts and must not become features; the post's own points may.
  auto surface = [](double a) { return std::abs(a) < 2 * M_PI / 180 ? 5.0 : 20.0 / std::cos(a); };
  const auto ring = scanRing(-20, 20, surface);
  FeatureOptions o;
  o.sectors = 1;
  const auto labels = labelRing(ring, o);
  for (size_t i = 0; i + 1 < ring.size(); ++i) {
    const float r0 = ring[i].p.norm(), r1 = ring[i + 1].p.norm();
    if (r0 > 15 && r1 < 6) {  // far -> near: the far points just before the jump
      for (size_t j = i >= 4 ? i - 4 : 0; j <= i; ++j) EXPECT_EQ(labels[j], FeatureLabel::None) << j;
    }
    if (r0 < 6 && r1 > 15) {
      for (size_t j = i + 1; j <= i + 5; ++j) EXPECT_EQ(labels[j], FeatureLabel::None) << j;
    }
  }
}

TEST(RingFeatures, GrazingBeamIsRejected) {
  // A wall nearly parallel to the beams: spacing between neighbours exceeds 2 % of the range.
  auto grazing = [](double a) { return 2.0 / std::sin(a); };  // the wall y = 2 seen at 3..6 degrees
  const auto ring = scanRing(3, 6, grazing);
  const auto labels = labelRing(ring, FeatureOptions{});
  for (size_t i = 0; i < labels.size(); ++i) EXPECT_EQ(labels[i], FeatureLabel::None) << i;
}

TEST(RingFeatures, ExtractFeaturesSplitsByLaserAndOrdersByOffset) {
  // Two rings of the same wall, stored interleaved and in reverse time order.
  std::vector<LidarPoint> raw;
  std::vector<Eigen::Vector3f> points;
  const auto ring = scanRing(-20, 20, wall);
  for (int laser = 0; laser < 2; ++laser) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const size_t k = ring.size() - 1 - i;
      LidarPoint p;
      p.x = ring[k].p.x();
      p.y = ring[k].p.y();
      p.z = laser;
      p.laserNumber = uint8_t(laser * 40);
      p.offsetNs = int32_t(1000 * i);
      raw.push_back(p);
      points.emplace_back(p.x, p.y, p.z);
    }
  }
  const FeatureCloud cloud = extractFeatures(points, raw, FeatureOptions{});
  EXPECT_EQ(cloud.flat.size(), 2u * 6 * 4);
  EXPECT_EQ(cloud.lessFlat.size(), 2 * (ring.size() - 10));
}

}  // namespace hdprior
