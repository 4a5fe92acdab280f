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

// LOAM's feature sets: the edges are off by default (see FeatureOptions) but labelled here.
FeatureOptions loam() {
  FeatureOptions o;
  o.sharpPerSector = 2;
  o.lessSharpPerSector = 20;
  return o;
}

}  // namespace

TEST(RingFeatures, PlaneGivesFlatsAndNoEdges) {
  const auto ring = scanRing(-20, 20, wall);
  const auto labels = labelRing(ring, loam());
  EXPECT_EQ(countLabel(labels, FeatureLabel::Sharp), 0);
  EXPECT_EQ(countLabel(labels, FeatureLabel::LessSharp), 0);
  EXPECT_EQ(countLabel(labels, FeatureLabel::Flat), loam().sectors * loam().flatPerSector);
  // Every point with a full neighbourhood is at least less-flat.
  EXPECT_EQ(countLabel(labels, FeatureLabel::Flat) + countLabel(labels, FeatureLabel::LessFlat), int(ring.size()) - 10);
}

TEST(RingFeatures, CornerIsTheSharpestPoint) {
  const auto ring = scanRing(30, 60, corner);
  FeatureOptions o = loam();
  o.sectors = 1;
  const auto labels = labelRing(ring, o);
  std::vector<int> sharp;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == FeatureLabel::Sharp) sharp.push_back(int(i));
  }
  ASSERT_GE(sharp.size(), 1u);
  const int cornerIndex = int(std::lround((45.0 - 30.0) / kStepDeg));
  EXPECT_LE(std::abs(sharp.front() - cornerIndex), 1) << "sharpest point " << sharp.front() << ", corner " << cornerIndex;
  for (int i : sharp) EXPECT_LE(std::abs(i - cornerIndex), 1);
  // Far from the corner the walls are flat.
  EXPECT_EQ(labels[10] == FeatureLabel::Flat || labels[10] == FeatureLabel::LessFlat, true);
  EXPECT_EQ(labels[labels.size() - 11] == FeatureLabel::Flat || labels[labels.size() - 11] == FeatureLabel::LessFlat, true);
}

TEST(RingFeatures, OccludedSideOfADepthJumpIsRejected) {
  // A near post (range 5) in front of a far wall (range 20): the wall points beside the post are
  // occluded-edge artefacts and must not become features; the post's own edge points may.
  auto surface = [](double a) { return std::abs(a) < 2 * M_PI / 180 ? 5.0 : 20.0 / std::cos(a); };
  const auto ring = scanRing(-20, 20, surface);
  FeatureOptions o = loam();
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
  const auto labels = labelRing(ring, loam());
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
  const FeatureCloud cloud = extractFeatures(points, raw, loam());
  EXPECT_TRUE(cloud.sharp.empty());
  EXPECT_EQ(cloud.flat.size(), 2u * 6 * 4);
  EXPECT_EQ(cloud.lessFlat.size(), 2 * (ring.size() - 10));
}

}  // namespace hdprior
