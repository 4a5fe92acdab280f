// Scan-to-map registration from a guess degrees off, as the constant-velocity guess is in a sharp
// turn: each re-association round gets part of the way back, so rounds go on while one still moves
// the pose, and stop once it has settled.
#include "engine/odom/feature_registration.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/geom/se2.h"
#include "engine/odom/voxel_feature_map.h"

namespace hdprior {
namespace {

// A walled yard 40 x 30 m with the ground and four pillars, sampled every 0.25 m: planes that fix
// all six degrees of freedom.
std::vector<Eigen::Vector3f> yard() {
  std::vector<Eigen::Vector3f> p;
  for (float a = -20; a <= 20; a += 0.25f)
    for (float z = 0.25f; z <= 4; z += 0.25f) p.emplace_back(a, -15, z), p.emplace_back(a, 15, z);
  for (float a = -15; a <= 15; a += 0.25f)
    for (float z = 0.25f; z <= 4; z += 0.25f) p.emplace_back(-20, a, z), p.emplace_back(20, a, z);
  for (float x = -19; x <= 19; x += 0.5f)
    for (float y = -14; y <= 14; y += 0.5f) p.emplace_back(x, y, 0.2f * std::sin(0.3f * x));
  for (const Eigen::Vector2f c : {Eigen::Vector2f(-8, -6), Eigen::Vector2f(7, -5), Eigen::Vector2f(-6, 7), Eigen::Vector2f(9, 6)})
    for (float z = 0.25f; z <= 3; z += 0.25f)
      for (float t = -1; t <= 1; t += 0.25f)
        p.emplace_back(c.x() + t, c.y() - 1, z), p.emplace_back(c.x() + t, c.y() + 1, z), p.emplace_back(c.x() - 1, c.y() + t, z),
            p.emplace_back(c.x() + 1, c.y() + t, z);
  return p;
}

double yawErrorDeg(const SE3& T) { return std::abs(yawOf(T)) * 180.0 / M_PI; }

TEST(FeatureRegistration, RoundsGoOnWhileAFarGuessStillMovesThePose) {
  const std::vector<Eigen::Vector3f> points = yard();
  VoxelFeatureMap map;
  map.add(points);
  SE3 guess = SE3::Identity();
  guess.linear() = Eigen::AngleAxisd(12.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  guess.translation() = Eigen::Vector3d(0.4, -0.3, 0.0);

  RegistrationOptions two;
  two.maxOuterIterations = 2;
  const RegistrationResult fixed = registerFeatures(points, map, guess, two);
  const RegistrationResult onward = registerFeatures(points, map, guess, RegistrationOptions{});
  std::printf("a 12 deg guess: two rounds end %.3f deg and %.3f m off, rounds while the pose moves %.4f deg and %.4f m\n",
              yawErrorDeg(fixed.mapTEgo), fixed.mapTEgo.translation().norm(), yawErrorDeg(onward.mapTEgo),
              onward.mapTEgo.translation().norm());
  EXPECT_GT(yawErrorDeg(fixed.mapTEgo), 0.1);
  EXPECT_LT(yawErrorDeg(onward.mapTEgo), 0.05);
  EXPECT_LT(onward.mapTEgo.translation().norm(), 0.02);
}

TEST(FeatureRegistration, AGoodGuessTakesNoMoreRoundsThanItsMinimum) {
  const std::vector<Eigen::Vector3f> points = yard();
  VoxelFeatureMap map;
  map.add(points);
  SE3 guess = SE3::Identity();
  guess.translation() = Eigen::Vector3d(0.05, 0.02, 0.0);
  RegistrationOptions two;
  two.maxOuterIterations = 2;
  const RegistrationResult a = registerFeatures(points, map, guess, two);
  const RegistrationResult b = registerFeatures(points, map, guess, RegistrationOptions{});
  EXPECT_TRUE(a.mapTEgo.isApprox(b.mapTEgo, 1e-12)) << "settled after two rounds: the same pose, bit for bit";
  EXPECT_TRUE(a.covariance.isApprox(b.covariance, 1e-12));
}

}  // namespace
}  // namespace hdprior
