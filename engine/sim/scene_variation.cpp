#include "engine/sim/scene_variation.h"

#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/geom/angles.h"
#include "engine/sim/splitmix.h"

namespace hdprior {
namespace {

constexpr int kLasers = 64;

struct Draw {
  std::mt19937_64 rng;
  double operator()(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Eigen::Vector3d direction() {
    const double z = (*this)(-1.0, 1.0), a = (*this)(0.0, 2.0 * std::numbers::pi), r = std::sqrt(1.0 - z * z);
    return {r * std::cos(a), r * std::sin(a), z};
  }
};

void drawRoadside(Draw& draw, RoadsideOptions& r) {
  const double kerb = draw(0.03, 0.21), spread = draw(0.0, 0.04);
  r.kerbHeightMin = std::max(0.0, kerb - spread);
  r.kerbHeightMax = std::min(0.25, kerb + spread);
  r.kerbWavelength = draw(40.0, 120.0);
  r.noKerbFraction = draw(0.0, 0.3);
  r.mountableFraction = draw(0.0, 0.5);
  r.mountableWidth = draw(0.3, 0.6);
  r.kerbCutSpacing = draw(25.0, 80.0);
  r.kerbCutLengthMin = 3.0;
  r.kerbCutLengthMax = 6.0;
  r.gutterWidth = draw(0.3, 0.5);
  r.gutterDepth = draw(0.02, 0.05);
  r.camber = draw(0.01, 0.03);
  r.camberCap = draw(2.5, 5.0);
  r.sidewalkWidthMin = draw(2.0, 4.5);
  r.sidewalkWidthMax = std::min(6.0, r.sidewalkWidthMin + draw(0.0, 2.0));
  r.sidewalkSlope = draw(0.01, 0.04);
  r.terrainRelief = draw(0.02, 0.08);
  r.roadReflectivity = uint8_t(std::lround(draw(8.0, 18.0)));
  r.sidewalkReflectivity = uint8_t(std::lround(draw(22.0, 45.0)));
  r.terrainReflectivity = uint8_t(std::lround(draw(10.0, 35.0)));
  r.mapErrorAmplitude = draw(0.0, 0.3);
  r.mapErrorWavelength = draw(25.0, 64.0);  // its waves span 0.8-1.25 of it: 20-80 m
}

void drawLidar(Draw& draw, SceneVariation& v) {
  const double elevation = draw(0.0, 0.2) * kDegree, bias = draw(0.0, 0.03);
  for (int l = 0; l < kLasers; ++l) {
    v.elevationErrors.push_back(draw(-elevation, elevation));
    v.rangeBiases.push_back(draw(-bias, bias));
  }
  const Eigen::Vector3d axis = draw.direction();
  const double angle = draw(0.0, 0.3) * kDegree;
  const Eigen::Vector3d shift = draw.direction();
  const double distance = draw(0.0, 0.02);
  v.downRotationError = angle * axis;
  v.downTranslationError = distance * shift;
}

// Around the paint and asphalt of the real sweep (docs/simulator.md): within 8 m, 28 % of the road
// returns on a mapped lane line and 13 % of the others pass the paint check's 1.7x the median, and
// 14 runs of bright returns a sweep lie off the mapped lines.
void drawRoadSurface(Draw& draw, RoadsideOptions& r) {
  r.paintContrast = draw(1.4, 2.0);
  r.paintWear = draw(0.1, 0.4);
  r.asphaltPatchShare = draw(0.03, 0.07);
  r.asphaltFleckShare = draw(0.06, 0.12);
  r.asphaltPatchGain = draw(2.0, 3.0);
}

}  // namespace

const char* familyName(SceneFamily family) { return family == SceneFamily::Tuning ? "tuning" : "validation"; }

SceneFamily parseSceneFamily(const std::string& name) {
  if (name == "tuning") return SceneFamily::Tuning;
  if (name == "validation") return SceneFamily::Validation;
  throw Error("option --family", "'" + name + "' is not tuning or validation");
}

SceneVariation drawSceneVariation(SceneFamily family, uint64_t seed) {
  // Each family its own stream: the same seed draws unrelated worlds in the two families.
  const uint64_t stream = family == SceneFamily::Tuning ? 0x74756e696e67ULL : 0x76616c6964ULL;
  Draw draw{std::mt19937_64(splitmix(splitmix(seed) ^ stream))};
  SceneVariation v;
  v.family = family;
  v.seed = seed;
  v.minRoadWidth = draw(6.0, 9.0);
  v.maxRoadWidth = draw(18.0, 30.0);
  v.junctionMargin = draw(4.0, 10.0);
  v.parked = draw(0.0, 0.9);
  v.buildingDensity = draw(0.1, 0.8);
  v.buildingDensityVariation = draw(0.0, 0.8);
  v.treeDensity = draw(0.1, 0.5);
  v.vegetationDensity = draw(0.1, 0.6);
  v.islandDensity = draw(0.0, 0.5);
  drawRoadside(draw, v.roadside);
  drawLidar(draw, v);
  drawRoadSurface(draw, v.roadside);  // last, so that the draws before it stay as they were
  return v;
}

void SceneVariation::applyTo(TownOptions& town) const {
  if (neutral()) return;
  town.minRoadWidth = minRoadWidth;
  town.maxRoadWidth = maxRoadWidth;
  town.threeLaneWidth = std::max(town.twoLaneWidth, 21.0);
  town.junctionMargin = junctionMargin;
}

void SceneVariation::applyTo(SceneOptions& scene) const {
  if (neutral()) return;
  scene.parked = parked;
  scene.buildingDensity = buildingDensity;
  scene.buildingDensityVariation = buildingDensityVariation;
  scene.treeDensity = treeDensity;
  scene.vegetationDensity = vegetationDensity;
  scene.islandDensity = islandDensity;
  scene.sidewalkWidth = 0.5 * (roadside.sidewalkWidthMin + roadside.sidewalkWidthMax);
  scene.roadside = roadside;
}

void SceneVariation::applyTo(LidarModel& lidar) const {
  if (neutral()) return;
  for (LidarUnit& unit : lidar.units) {
    const size_t first = size_t(unit.firstLaserNumber), n = unit.elevations.size();
    if (first + n <= elevationErrors.size())
      unit.elevationErrors.assign(elevationErrors.begin() + long(first), elevationErrors.begin() + long(first + n));
    if (first + n <= rangeBiases.size())
      unit.rangeBiases.assign(rangeBiases.begin() + long(first), rangeBiases.begin() + long(first + n));
    if (unit.name == "down_lidar") {
      SE3 error = SE3::Identity();
      if (downRotationError.norm() > 0.0)
        error.linear() = Eigen::AngleAxisd(downRotationError.norm(), downRotationError.normalized()).toRotationMatrix();
      error.translation() = downTranslationError;
      unit.trueEgoTSensor = unit.egoTSensor * error;
    }
  }
}

std::string sceneVariationToJson(const SceneVariation& v) {
  nlohmann::json j;
  j["family"] = v.family ? familyName(*v.family) : "none";
  j["seed"] = v.seed;
  j["town"] = {{"min_road_width_m", v.minRoadWidth}, {"max_road_width_m", v.maxRoadWidth},
               {"junction_margin_m", v.junctionMargin}};
  j["objects"] = {{"parked", v.parked},
                  {"building_density", v.buildingDensity},
                  {"building_density_variation", v.buildingDensityVariation},
                  {"tree_density", v.treeDensity},
                  {"vegetation_density", v.vegetationDensity},
                  {"island_density", v.islandDensity}};
  const RoadsideOptions& r = v.roadside;
  j["roadside"] = {{"kerb_height_m", {r.kerbHeightMin, r.kerbHeightMax}},
                   {"kerb_wavelength_m", r.kerbWavelength},
                   {"no_kerb_fraction", r.noKerbFraction},
                   {"mountable_fraction", r.mountableFraction},
                   {"mountable_width_m", r.mountableWidth},
                   {"kerb_cut_spacing_m", r.kerbCutSpacing},
                   {"kerb_cut_length_m", {r.kerbCutLengthMin, r.kerbCutLengthMax}},
                   {"gutter_width_m", r.gutterWidth},
                   {"gutter_depth_m", r.gutterDepth},
                   {"camber", r.camber},
                   {"camber_cap_m", r.camberCap},
                   {"sidewalk_width_m", {r.sidewalkWidthMin, r.sidewalkWidthMax}},
                   {"sidewalk_slope", r.sidewalkSlope},
                   {"terrain_relief_m", r.terrainRelief},
                   {"reflectivity", {{"road", r.roadReflectivity}, {"sidewalk", r.sidewalkReflectivity},
                                     {"terrain", r.terrainReflectivity}}},
                   {"paint_contrast", r.paintContrast},
                   {"paint_wear", r.paintWear},
                   {"asphalt_patch_share", r.asphaltPatchShare},
                   {"asphalt_fleck_share", r.asphaltFleckShare},
                   {"asphalt_patch_gain", r.asphaltPatchGain},
                   {"map_error_amplitude_m", r.mapErrorAmplitude},
                   {"map_error_wavelength_m", r.mapErrorWavelength}};
  std::vector<double> elevationDeg;
  for (double e : v.elevationErrors) elevationDeg.push_back(e / kDegree);
  j["lidar"] = {{"elevation_error_deg", elevationDeg},
                {"range_bias_m", v.rangeBiases},
                {"down_lidar_rotation_error_deg",
                 {v.downRotationError.x() / kDegree, v.downRotationError.y() / kDegree, v.downRotationError.z() / kDegree}},
                {"down_lidar_rotation_error_angle_deg", v.downRotationError.norm() / kDegree},
                {"down_lidar_translation_error_m",
                 {v.downTranslationError.x(), v.downTranslationError.y(), v.downTranslationError.z()}}};
  return j.dump(2) + "\n";
}

}  // namespace hdprior
