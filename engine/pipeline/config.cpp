#include "engine/pipeline/config.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <variant>
#include <vector>

#include "assets/default_config_json.h"
#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"

namespace hdprior {
namespace {

using nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

// An enum stored as one of its names.
struct Choice {
  std::vector<const char*> names;
  std::function<int()> get;
  std::function<void(int)> set;
};

template <class E>
Choice choice(E* e, std::vector<const char*> names) {
  return {std::move(names), [e] { return int(*e); }, [e](int v) { *e = E(v); }};
}

struct Field {
  const char* key;
  std::variant<int*, double*, bool*, std::string*, std::vector<double>*, std::vector<int>*, Eigen::Vector3d*, Choice> value;
  double lo = -kInf, hi = kInf;  // inclusive range of numbers (of every element of an array)
};
using Sections = std::map<std::string, std::vector<Field>>;  // section path -> its fields

// Every configurable value with its JSON key and allowed range, in one place.
Sections sectionsOf(Config& c) {
  FeatureOptions& f = c.odometry.features;
  RegistrationOptions& r = c.odometry.registration;
  LocalMapOptions& m = c.odometry.localMap;
  GroundSegmentationOptions& g = c.roadPoints.ground;
  RoadPointOptions& rp = c.roadPoints.road;
  MatchOptions& mt = c.match;
  return {
      {"odometry", {}},
      {"odometry.features",
       {{"neighbours", &f.neighbours, 1, 20},
        {"sectors", &f.sectors, 1, 64},
        {"sharp_per_sector", &f.sharpPerSector, 0, 1000},
        {"less_sharp_per_sector", &f.lessSharpPerSector, 0, 10000},
        {"flat_per_sector", &f.flatPerSector, 0, 1000},
        {"edge_curvature", &f.edgeCurvature, 0, 10},
        {"plane_curvature", &f.planeCurvature, 0, 10},
        {"min_range", &f.minRange, 0, 1000},
        {"max_range", &f.maxRange, 0, 10000},
        {"occlusion_ratio", &f.occlusionRatio, 0, 10},
        {"parallel_beam_ratio", &f.parallelBeamRatio, 0, 10},
        {"max_gap_deg", &f.maxGapDeg, 0, 360}}},
      {"odometry.deskew", {{"mode", &c.odometry.deskew.mode}}},
      {"odometry.registration",
       {{"outer_iterations", &r.outerIterations, 1, 100},
        {"solver_iterations", &r.solverIterations, 1, 1000},
        {"huber_scale", &r.huberScale, 1e-6, 100},
        {"max_correspondence", &r.maxCorrespondence, 1e-3, 100},
        {"edge_downsample", &r.edgeDownsample, 1e-3, 100},
        {"plane_downsample", &r.planeDownsample, 1e-3, 100},
        {"scan_to_scan_guess", &r.scanToScanGuess},
        {"threads", &r.threads, 1, 64}}},
      {"odometry.local_map",
       {{"voxel_size", &m.voxelSize, 0.05, 100},
        {"max_points_per_voxel", &m.maxPointsPerVoxel, 1, 10000},
        {"min_point_spacing", &m.minPointSpacing, 0, 100},
        {"radius", &m.radius, 1, 100000}}},
      // Ranges checked by odometryDriftProblem (the scale's is open) after reading.
      {"odometry.drift",
       {{"scale", &c.odometry.drift.scale},
        {"yaw_deg_per_100m", &c.odometry.drift.yawDegPer100m},
        {"pitch_deg_per_100m", &c.odometry.drift.pitchDegPer100m}}},
      {"keyframes", {{"distance", &c.keyframes.distance, 0, 100000}, {"rotation_deg", &c.keyframes.rotationDeg, 0, 360}}},
      {"road_points", {{"thin_cell", &c.roadPoints.thinCell, 0, 10}, {"submap", &c.submapRoadPoints}}},
      {"road_points.ground",
       {{"ground_z", &g.groundZ, -10, 10},
        {"min_range", &g.minRange, 0, 1000},
        {"max_range", &g.maxRange, 0, 1000},
        {"zone_radii", &g.zoneRadii, 0.1, 1000},
        {"zone_rings", &g.zoneRings, 1, 100},
        {"zone_sectors", &g.zoneSectors, 1, 1000},
        {"min_bin_points", &g.minBinPoints, 3, 10000},
        {"seed_points", &g.seedPoints, 1, 10000},
        {"seed_height", &g.seedHeight, 0, 10},
        {"plane_distance", &g.planeDistance, 0.001, 10},
        {"iterations", &g.iterations, 1, 100},
        {"max_tilt_deg", &g.maxTiltDeg, 0, 90},
        {"max_elevation", &g.maxElevation, 0, 100},
        {"elevation_per_metre", &g.elevationPerMetre, 0, 10}}},
      {"road_points.road",
       {{"ground_z", &rp.groundZ, -10, 10},
        {"max_range", &rp.maxRange, 0, 1000},
        {"max_step", &rp.maxStep, 0, 10},
        {"step_per_metre", &rp.stepPerMetre, 0, 10},
        {"max_camber", &rp.maxCamber, 0, 0.5},
        {"max_gap", &rp.maxGap, 0, 1000},
        {"window", &rp.window, 0, 1000},
        {"max_skipped", &rp.maxSkipped, 0, 10000},
        {"gutter_rise", &rp.gutterRise, 0, 10},
        {"gutter_window", &rp.gutterWindow, 1e-3, 100},
        {"seed_half_width", &rp.seedHalfWidth, 0, 100},
        {"seed_tolerance", &rp.seedTolerance, 0, 10},
        {"seed_tolerance_per_metre", &rp.seedTolerancePerMetre, 0, 10},
        {"lane_seeds", &rp.laneSeeds},
        {"lane_step", &rp.laneStep, 0.001, 10},
        {"grade_length", &rp.gradeLength, 0.1, 1000},
        {"lane_object_height", &rp.laneObjectHeight, 0.01, 100},
        {"lane_end_length", &rp.laneEndLength, 0, 100}}},
      {"match",
       {{"backend", choice(&mt.backend, {"ndt2d", "pcl"})},
        {"cell_sizes", &mt.cellSizes, 0.1, 100},
        {"outlier_ratio", &mt.outlierRatio, 0, 0.999},
        {"lookup", choice(&mt.lookup, {"containing_cell", "four_nearest", "bilinear"})},
        {"max_iterations", &mt.maxIterations, 1, 1000},
        {"max_coarse_stride", &mt.maxCoarseStride, 1, 1000},
        {"max_step_gain", &mt.maxStepGain, 1, 100},
        {"max_step_cells", &mt.maxStepCells, 0.01, 100},
        {"max_step_yaw_deg", &mt.maxStepYawDeg, 0.01, 180},
        {"translation_tolerance", &mt.translationTolerance, 0, 10},
        {"yaw_tolerance_deg", &mt.yawToleranceDeg, 0, 10},
        {"time_budget_ms", &mt.timeBudgetMs, 0.001, 1e6},
        {"pcl_resolution", &mt.pclResolution, 0.05, 100},
        {"pcl_step_size", &mt.pclStepSize, 1e-4, 10},
        {"pcl_epsilon", &mt.pclEpsilon, 0, 10},
        {"pcl_max_iterations", &mt.pclMaxIterations, 1, 1000},
        {"pcl_target_spacing", &mt.pclTargetSpacing, 0.01, 100},
        {"curb_refinement", &mt.curbRefinement},
        {"curb_huber", &mt.curbHuber, 1e-3, 10},
        {"curb_max_distance", &mt.curbMaxDistance, 1e-3, 100},
        {"min_curb_points", &mt.minCurbPoints, 1, 100000},
        {"curb_lateral_only", &mt.curbLateralOnly},
        {"per_cell_information", &mt.perCellInformation},
        {"yaw_length", &mt.yawLength, 0.01, 1000},
        {"boundary_band", &mt.boundaryBand, 0, 100},
        {"degenerate_ratio", &mt.degenerateRatio, 0, 1},
        {"min_boundary_points", &mt.minBoundaryPoints, 0, 1e6},
        {"min_information", &mt.minInformation, 0, 1e9},
        {"min_points", &mt.minPoints, 0, 10000000},
        {"min_inlier_ratio", &mt.minInlierRatio, 0, 1},
        {"prediction_sigma", &mt.predictionSigma, 1e-6, 1000},
        {"gate_chi2", &mt.gateChi2, 0, 1e9},
        {"min_score_per_point", &mt.minScorePerPoint, -1e9, 1e9},
        {"stale_regions", &mt.staleRegions},
        {"stale_region_size", &mt.staleRegionSize, 0.1, 1000},
        {"stale_distance", &mt.staleDistance, 0, 1000},
        {"stale_distance_per_metre", &mt.staleDistancePerMetre, 0, 10},
        {"stale_share", &mt.staleShare, 0, 1},
        {"evidence_uncertainty", &mt.evidenceUncertainty},
        {"evidence_share", &mt.evidenceShare, 0, 0.999},
        {"evidence_spill_share", &mt.evidenceSpillShare, 0, 1},
        {"evidence_min_points", &mt.evidenceMinPoints, 0, 1000000},
        {"evidence_margin", &mt.evidenceMargin, -10, 10},
        {"evidence_stride", &mt.evidenceStride, 1, 1000},
        {"evidence_curb_band", &mt.evidenceCurbBand, 1e-3, 10},
        {"evidence_curb_share", &mt.evidenceCurbShare, 0, 0.999},
        {"evidence_max_offset", &mt.evidenceMaxOffset, 0.01, 100},
        {"evidence_max_yaw_deg", &mt.evidenceMaxYawDeg, 0.01, 90},
        {"evidence_kappa", &mt.evidenceKappa, 0.01, 100},
        {"map_sigma", &mt.mapSigma, 0, 10},
        {"map_sigma_yaw_deg", &mt.mapSigmaYawDeg, 0, 10},
        {"max_sigma_along", &mt.maxSigmaAlong, 1e-3, 1e6},
        {"max_sigma_lateral", &mt.maxSigmaLateral, 1e-3, 1e6},
        {"max_sigma_yaw_deg", &mt.maxSigmaYawDeg, 1e-3, 1e6}}},
      {"prior",
       {{"ego_height", &c.prior.egoHeight, -10, 10},
        {"altitude_sigma", &c.prior.altitudeSigma, 1e-4, 100},
        {"along_track_sigma", &c.prior.alongTrackSigma, 0, 1000},
        {"innovation_gate_probability", &c.prior.innovationGateProbability, 0, 0.999999},
        {"reanchor_priors", &c.prior.reanchorPriors, 0, 1000}}},
      {"graph",
       {{"prior_huber", &c.graph.priorHuber, 0, 1e6},
        {"max_iterations", &c.graph.maxIterations, 1, 10000},
        {"odometry_translation_sigma_per_m", &c.graph.odometryTranslationSigmaPerM, 0, 10},
        {"odometry_rotation_sigma_deg_per_m", &c.graph.odometryRotationSigmaDegPerM, 0, 180},
        {"given_odometry_translation_sigma_per_m", &c.graph.givenOdometryTranslationSigmaPerM, 0, 10},
        {"given_odometry_rotation_sigma_deg_per_m", &c.graph.givenOdometryRotationSigmaDegPerM, 0, 180},
        {"map_error_length", &c.graph.mapErrorLength, 0, 1e6},
        {"drift_model_margin_nats", &c.graph.driftModelMarginNats, 0, 1e6}}},
      {"sweeps", {{"max_unreadable_share", &c.maxUnreadableSweepShare, 0, 1}}},
  };
}

std::string rangeText(const Field& f) {
  std::string text = "[";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + string
  text += json(f.lo).dump();
  text += ", ";
  text += json(f.hi).dump();
  return text + "]";
}

template <class T>
T numberIn(const Field& f, const json& v, const std::string& key, const std::string& source) {
  const double d = std::is_same_v<T, int> ? double(json_reading::integer(v, key, source)) : json_reading::number(v, key, source);
  if (d < f.lo || d > f.hi) throw Error(source, key + " = " + v.dump() + " is out of range " + rangeText(f));
  return T(d);
}

template <class T>
std::vector<T> arrayIn(const Field& f, const json& v, const std::string& key, const std::string& source) {
  if (!v.is_array() || v.empty()) throw Error(source, key + " must be a non-empty array of numbers");
  std::vector<T> out;
  for (const json& e : v) out.push_back(numberIn<T>(f, e, key, source));
  return out;
}

void setField(const Field& f, const json& v, const std::string& key, const std::string& source) {
  struct Setter {
    const Field& f;
    const json& v;
    const std::string& key;
    const std::string& source;
    void operator()(bool* p) const {
      if (!v.is_boolean()) throw Error(source, key + " must be true or false");
      *p = v.get<bool>();
    }
    void operator()(std::string* p) const {
      if (!v.is_string()) throw Error(source, key + " must be a string");
      *p = v.get<std::string>();
    }
    void operator()(int* p) const { *p = numberIn<int>(f, v, key, source); }
    void operator()(double* p) const { *p = numberIn<double>(f, v, key, source); }
    void operator()(std::vector<double>* p) const { *p = arrayIn<double>(f, v, key, source); }
    void operator()(std::vector<int>* p) const { *p = arrayIn<int>(f, v, key, source); }
    void operator()(Eigen::Vector3d* p) const {
      const std::vector<double> a = arrayIn<double>(f, v, key, source);
      if (a.size() != 3) throw Error(source, key + " must be an array of 3 numbers");
      *p = {a[0], a[1], a[2]};
    }
    void operator()(const Choice& c) const {
      for (size_t i = 0; i < c.names.size(); ++i) {
        if (v.is_string() && v.get<std::string>() == c.names[i]) return c.set(int(i));
      }
      std::string names;
      for (const char* n : c.names) names += std::string(names.empty() ? "" : " or ") + "\"" + n + "\"";
      throw Error(source, key + " must be " + names);
    }
  };
  std::visit(Setter{f, v, key, source}, f.value);
}

struct Getter {
  json operator()(const Eigen::Vector3d* p) const { return {p->x(), p->y(), p->z()}; }
  json operator()(const Choice& c) const { return c.names.at(size_t(c.get())); }
  json operator()(const auto* p) const { return *p; }
};

json valueOf(const Field& f) { return std::visit(Getter{}, f.value); }

void readSection(const json& obj, const std::string& path, const Sections& sections, Config& c, const std::string& source) {
  if (!obj.is_object()) throw Error(source, (path.empty() ? std::string("the file") : path) + " must be a JSON object");
  for (const auto& [key, value] : obj.items()) {
    const std::string full = path.empty() ? key : path + "." + key;
    if (sections.count(full)) {
      readSection(value, full, sections, c, source);
      continue;
    }
    const auto it = sections.find(path);
    const Field* field = nullptr;
    if (it != sections.end()) {
      for (const Field& f : it->second) {
        if (key == f.key) field = &f;
      }
    }
    if (!field) throw Error(source, "unknown key " + full);
    setField(*field, value, full, source);
  }
}

// The keys of `text` set over `c`, then the checks across keys.
Config parseOnto(Config c, const std::string& text, const std::string& source) {
  const Sections sections = sectionsOf(c);
  readSection(json_reading::parse(text, source), "", sections, c, source);
  if (c.odometry.deskew.mode != "none" && c.odometry.deskew.mode != "constant_velocity") {
    throw Error(source, "odometry.deskew.mode must be \"none\" or \"constant_velocity\"");
  }
  if (const std::string problem = odometryDriftProblem(c.odometry.drift); !problem.empty()) {
    throw Error(source, "odometry.drift." + problem);
  }
  if (c.odometry.features.minRange >= c.odometry.features.maxRange) {
    throw Error(source, "odometry.features.min_range must be below max_range");
  }
  if (c.roadPoints.road.laneObjectHeight <= c.roadPoints.road.laneStep) {
    throw Error(source, "road_points.road.lane_object_height must be above lane_step");
  }
  const GroundSegmentationOptions& g = c.roadPoints.ground;
  if (g.zoneRadii.size() != g.zoneRings.size() || g.zoneRadii.size() != g.zoneSectors.size()) {
    throw Error(source, "road_points.ground.zone_radii, zone_rings and zone_sectors must have the same length");
  }
  if (!std::is_sorted(g.zoneRadii.begin(), g.zoneRadii.end()) || g.minRange >= g.zoneRadii.front()) {
    throw Error(source, "road_points.ground.zone_radii must increase from above min_range");
  }
  if (!std::is_sorted(c.match.cellSizes.rbegin(), c.match.cellSizes.rend())) {
    throw Error(source, "match.cell_sizes must go from coarse to fine (decreasing)");
  }
  return c;
}

}  // namespace

const std::string& defaultConfigText() {
  static const std::string text = assets::kDefaultConfigJson;
  return text;
}

const Config& defaultConfig() {
  static const Config config = parseOnto(Config{}, defaultConfigText(), "default_config.json (built in)");
  return config;
}

Config parseConfig(const std::string& text, const std::string& source) { return parseOnto(defaultConfig(), text, source); }

std::string formatConfig(const Config& config) {
  Config c = config;
  json root = json::object();
  for (const auto& [path, fields] : sectionsOf(c)) {
    std::string slashPath = "/" + path;
    for (char& ch : slashPath) if (ch == '.') ch = '/';
    json& section = root[json::json_pointer(slashPath)];
    if (section.is_null()) section = json::object();
    for (const Field& f : fields) {
      section[f.key] = valueOf(f);
    }
  }
  return root.dump(2) + "\n";
}

Config loadConfig(const std::filesystem::path& path) { return parseConfig(readFileText(path), path.string()); }

void saveConfig(const std::filesystem::path& path, const Config& config) { writeFileAtomically(path, formatConfig(config)); }

}  // namespace hdprior
