// Scene families: the draw is deterministic, within its ranges and different per family; the
// neutral default changes nothing; the drawn lidar errors reach the ray caster but not the
// calibration written.
#include "engine/geom/angles.h"
#include "engine/sim/scene_variation.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "engine/error.h"

namespace hdprior {
namespace {

TEST(SceneVariation, DrawIsDeterministicAndWithinRanges) {
  for (SceneFamily family : {SceneFamily::Tuning, SceneFamily::Validation}) {
    for (uint64_t seed = 0; seed < 200; ++seed) {
      const SceneVariation v = drawSceneVariation(family, seed);
      ASSERT_EQ(sceneVariationToJson(v), sceneVariationToJson(drawSceneVariation(family, seed)));
      ASSERT_TRUE(v.family);
      EXPECT_EQ(*v.family, family);
      const RoadsideOptions& r = v.roadside;
      EXPECT_GE(r.kerbHeightMin, 0.0);
      EXPECT_LE(r.kerbHeightMin, r.kerbHeightMax);
      EXPECT_LE(r.kerbHeightMax, 0.25);
      EXPECT_GE(r.noKerbFraction, 0.0);
      EXPECT_LE(r.noKerbFraction, 0.3);
      EXPECT_GE(r.mountableWidth, 0.3);
      EXPECT_LE(r.mountableWidth, 0.6);
      EXPECT_GE(r.kerbCutLengthMin, 3.0);
      EXPECT_LE(r.kerbCutLengthMax, 6.0);
      EXPECT_GE(r.gutterWidth, 0.3);
      EXPECT_LE(r.gutterWidth, 0.5);
      EXPECT_GE(r.gutterDepth, 0.02);
      EXPECT_LE(r.gutterDepth, 0.05);
      EXPECT_GE(r.camber, 0.01);
      EXPECT_LE(r.camber, 0.03);
      EXPECT_GE(r.sidewalkWidthMin, 2.0);
      EXPECT_LE(r.sidewalkWidthMin, r.sidewalkWidthMax);
      EXPECT_LE(r.sidewalkWidthMax, 6.0);
      EXPECT_GE(r.sidewalkSlope, 0.01);
      EXPECT_LE(r.sidewalkSlope, 0.04);
      EXPECT_GE(r.mapErrorAmplitude, 0.0);
      EXPECT_LE(r.mapErrorAmplitude, 0.3);
      EXPECT_GE(r.paintContrast, 1.4);
      EXPECT_LE(r.paintContrast, 2.0);
      EXPECT_GE(r.paintWear, 0.1);
      EXPECT_LE(r.paintWear, 0.4);
      EXPECT_GE(r.asphaltPatchShare, 0.03);
      EXPECT_LE(r.asphaltPatchShare, 0.07);
      EXPECT_GE(r.asphaltFleckShare, 0.06);
      EXPECT_LE(r.asphaltFleckShare, 0.12);
      EXPECT_GE(r.asphaltPatchGain, 2.0);
      EXPECT_LE(r.asphaltPatchGain, 3.0);
      EXPECT_GE(0.8 * r.mapErrorWavelength, 20.0);
      EXPECT_LE(1.25 * r.mapErrorWavelength, 80.0);
      EXPECT_GE(v.parked, 0.0);
      EXPECT_LE(v.parked, 0.9);
      EXPECT_GE(v.buildingDensity, 0.1);
      EXPECT_LE(v.buildingDensity, 0.8);
      EXPECT_LE(v.maxRoadWidth, 30.0);
      EXPECT_GE(v.maxRoadWidth, 18.0);
      ASSERT_EQ(v.elevationErrors.size(), 64u);
      ASSERT_EQ(v.rangeBiases.size(), 64u);
      for (double e : v.elevationErrors) EXPECT_LE(std::abs(e), 0.2 * kDegree);
      for (double b : v.rangeBiases) EXPECT_LE(std::abs(b), 0.03);
      EXPECT_LE(v.downRotationError.norm(), 0.3 * kDegree);
      EXPECT_LE(v.downTranslationError.norm(), 0.02);
    }
  }
}

TEST(SceneVariation, DrawsSpanTheirRanges) {
  double lo = 1.0, hi = 0.0, maxError = 0.0;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const SceneVariation v = drawSceneVariation(SceneFamily::Tuning, seed);
    lo = std::min(lo, v.roadside.mapErrorAmplitude);
    hi = std::max(hi, v.roadside.mapErrorAmplitude);
    maxError = std::max(maxError, v.downRotationError.norm());
  }
  EXPECT_LT(lo, 0.03);
  EXPECT_GT(hi, 0.27);
  EXPECT_GT(maxError, 0.25 * kDegree);
}

TEST(SceneVariation, TuningAndValidationDrawDifferentWorldsForTheSameSeed) {
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const SceneVariation t = drawSceneVariation(SceneFamily::Tuning, seed);
    const SceneVariation v = drawSceneVariation(SceneFamily::Validation, seed);
    EXPECT_NE(t.roadside.kerbHeightMax, v.roadside.kerbHeightMax) << seed;
    EXPECT_NE(t.parked, v.parked) << seed;
    EXPECT_NE(t.elevationErrors, v.elevationErrors) << seed;
  }
  EXPECT_NE(drawSceneVariation(SceneFamily::Tuning, 1).parked, drawSceneVariation(SceneFamily::Tuning, 2).parked);
}

TEST(SceneVariation, FamilyNamesParseAndOthersAreOptionErrors) {
  EXPECT_EQ(parseSceneFamily("tuning"), SceneFamily::Tuning);
  EXPECT_EQ(parseSceneFamily("validation"), SceneFamily::Validation);
  try {
    parseSceneFamily("test");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "option --family");
  }
}

TEST(SceneVariation, NeutralDefaultChangesNoOption) {
  const SceneVariation neutral;
  EXPECT_TRUE(neutral.neutral());
  TownOptions town;
  SceneOptions scene;
  scene.parked = 0.3;  // what --parked gave stays
  LidarModel lidar = argoverseLikeLidar();
  neutral.applyTo(town);
  neutral.applyTo(scene);
  neutral.applyTo(lidar);
  const TownOptions defaultTown;
  EXPECT_EQ(town.maxRoadWidth, defaultTown.maxRoadWidth);
  EXPECT_EQ(town.minRoadWidth, defaultTown.minRoadWidth);
  EXPECT_EQ(town.junctionMargin, defaultTown.junctionMargin);
  EXPECT_EQ(town.threeLaneWidth, defaultTown.threeLaneWidth);
  EXPECT_EQ(scene.parked, 0.3);
  EXPECT_FALSE(scene.roadside);
  EXPECT_EQ(scene.vegetationDensity, 0.0);
  EXPECT_EQ(scene.islandDensity, 0.0);
  EXPECT_EQ(scene.buildingDensityVariation, 0.0);
  for (const LidarUnit& u : lidar.units) EXPECT_TRUE(u.ideal()) << u.name;
}

TEST(SceneVariation, WrittenCalibrationDiffersFromTheRayCastOneByTheDrawnExtrinsicError) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const SceneVariation v = drawSceneVariation(SceneFamily::Validation, seed);
    LidarModel lidar = argoverseLikeLidar();
    v.applyTo(lidar);
    const SensorCalibration written = lidar.calibration(), nominal = argoverseLikeLidar().calibration();
    for (const LidarUnit& u : lidar.units) {
      // What is written is the nominal calibration; the rays leave from the true mounting.
      EXPECT_TRUE(written.at(u.name).isApprox(nominal.at(u.name), 1e-15)) << u.name;
      ASSERT_EQ(u.elevationErrors.size(), 32u);
      ASSERT_EQ(u.rangeBiases.size(), 32u);
      EXPECT_EQ(u.elevationErrors[5], v.elevationErrors[size_t(u.firstLaserNumber) + 5]);
      EXPECT_EQ(u.rangeBiases[7], v.rangeBiases[size_t(u.firstLaserNumber) + 7]);
      if (u.name != "down_lidar") {
        EXPECT_FALSE(u.trueEgoTSensor) << u.name;
        continue;
      }
      ASSERT_TRUE(u.trueEgoTSensor);
      const SE3 delta = written.at(u.name).inverse() * *u.trueEgoTSensor;
      const double angle = Eigen::AngleAxisd(delta.rotation()).angle();
      EXPECT_NEAR(angle, v.downRotationError.norm(), 1e-9);
      EXPECT_NEAR(delta.translation().norm(), v.downTranslationError.norm(), 1e-12);
      EXPECT_NEAR((u.trueEgoTSensor->translation() - written.at(u.name).translation()).norm(),
                  v.downTranslationError.norm(), 1e-12);
      EXPECT_GT(angle + delta.translation().norm(), 0.0);
    }
  }
}

}  // namespace
}  // namespace hdprior
