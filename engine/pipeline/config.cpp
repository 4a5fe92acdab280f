#include "engine/pipeline/config.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <limits>
#include <variant>
#include <vector>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"
#include "engine/pipeline/config_schema.h"

namespace hdprior {
namespace {

using nlohmann::json;

// A value stored as one of its names: an enum, or a string with a closed set of values.
struct Choice {
  std::vector<const char*> names;
  std::function<size_t()> get;
  std::function<void(size_t)> set;
};

template <class E>
Choice choice(E* e, std::vector<const char*> names) {
  return {std::move(names), [e] { return size_t(*e); }, [e](size_t i) { *e = E(i); }};
}

Choice choice(std::string* s, std::vector<const char*> names) {
  return {names, [s, names] { return size_t(std::find(names.begin(), names.end(), *s) - names.begin()); },
          [s, names](size_t i) { *s = names[i]; }};
}

// "[0, 1)": inclusive with a bracket, exclusive with a parenthesis.
struct Range {
  double lo = 0, hi = 0;
  bool loOpen = false, hiOpen = false;

  explicit Range(const std::string& text) {
    char* end = nullptr;
    loOpen = text.front() == '(';
    lo = std::strtod(text.c_str() + 1, &end);
    hi = std::strtod(end + 1, &end);
    hiOpen = *end == ')';
  }
  bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
};

struct Field {
  const char* key;
  std::variant<int*, double*, std::vector<double>*, Eigen::Vector3d*, Choice> value;
  const char* range;  // of a number, or of every element of an array; "" for a choice
  const char* unit;
  const char* description;
};
struct Section {
  std::string path;
  std::vector<Field> fields;
};

// The schema: every key of the configuration, once, bound to the member of `c` that holds it. A
// member's initialiser is the key's default.
std::vector<Section> schemaOf(Config& c) {
  FeatureOptions& f = c.odometry.features;
  RegistrationOptions& r = c.odometry.registration;
  LocalMapOptions& m = c.odometry.localMap;
  GroundSegmentationOptions& g = c.roadPoints.ground;
  RoadPointOptions& rp = c.roadPoints.road;
  MatchOptions& mt = c.match;
  PosePriorOptions& p = c.prior;
  PoseGraphOptions& gr = c.graph;
  return {
      {"vehicle",
       {{"ego_height", &p.egoHeight, "[0, 10]", "m", "height of the ego origin above the road surface (Argoverse 2: 0.32)"}}},
      {"odometry.features",
       {{"sectors", &f.sectors, "[1, 64]", "", "sectors per laser ring; each picks its own plane features"},
        {"flat_per_sector", &f.flatPerSector, "[1, 1000]", "", "plane features picked per sector, the flattest first"},
        {"plane_curvature", &f.planeCurvature, "(0, 1]", "", "LOAM curvature below which a point may be a plane feature"},
        {"min_range", &f.minRange, "[0, 1000]", "m", "nearer returns (the vehicle itself) are not features"},
        {"max_range", &f.maxRange, "(0, 10000]", "m", "farther returns are not features"}}},
      {"odometry.deskew",
       {{"mode", choice(&c.odometry.deskew.mode, {"none", "constant_velocity"}), "", "",
         "none: sweeps are stored motion-compensated (Argoverse 2); constant_velocity: deskew raw sweeps by offset_ns"}}},
      {"odometry.registration",
       {{"outer_iterations", &r.outerIterations, "[1, 100]", "", "re-association rounds of scan-to-map registration"},
        {"solver_iterations", &r.solverIterations, "[1, 1000]", "", "Ceres iterations per round"},
        {"huber_scale", &r.huberScale, "(0, 100]", "m", "robust loss scale of the point-to-plane residuals"},
        {"max_correspondence", &r.maxCorrespondence, "(0, 10]", "m", "nearest-neighbour gate of a correspondence"},
        {"plane_downsample", &r.planeDownsample, "(0, 100]", "m", "voxel size of the scan's plane queries"},
        {"threads", &r.threads, "[1, 64]", "", "threads of the correspondence search and feature extraction"}}},
      {"odometry.local_map",
       {{"voxel_size", &m.voxelSize, "[0.1, 100]", "m", "voxel size of the local map's hash"},
        {"max_points_per_voxel", &m.maxPointsPerVoxel, "[1, 10000]", "", "points kept per voxel"},
        {"min_point_spacing", &m.minPointSpacing, "[0, 100]", "m", "a new point this close to one in its voxel is dropped"},
        {"radius", &m.radius, "[1, 100000]", "m", "voxels farther than this from the vehicle are removed"}}},
      {"keyframes",
       {{"distance", &c.keyframes.distance, "[0, 100000]", "m", "a keyframe after this distance travelled ..."},
        {"rotation_deg", &c.keyframes.rotationDeg, "[0, 360]", "deg", "... or this much turned"}}},
      {"road_points",
       {{"thin_cell", &c.roadPoints.thinCell, "[0, 10]", "m", "road points are thinned to one per cell of this size (0: all)"}}},
      {"road_points.ground",
       {{"min_range", &g.minRange, "[0, 8)", "m", "nearer returns hit the vehicle (below the first zone's 8 m)"},
        {"max_range", &g.maxRange, "(0, 1000]", "m", "farther returns are not segmented"},
        {"seed_height", &g.seedHeight, "(0, 10]", "m", "a bin's plane is fitted to points up to this above its lowest"},
        {"plane_distance", &g.planeDistance, "(0, 10]", "m", "ground: this close to the bin's plane"},
        {"max_tilt_deg", &g.maxTiltDeg, "(0, 90)", "deg", "steeper bin planes are walls, cars, vegetation"},
        {"max_elevation", &g.maxElevation, "[0, 100]", "m", "a bin's plane may lie this far above the expected road level ..."},
        {"elevation_per_metre", &g.elevationPerMetre, "[0, 10]", "m/m", "... plus this per metre of range (slopes)"}}},
      {"road_points.road",
       {{"max_range", &rp.maxRange, "(0, 1000]", "m", "road points farther from the origin are not used"},
        {"max_step", &rp.maxStep, "(0, 10]", "m", "height change between neighbouring road points that ends a ring's walk (a kerb) ..."},
        {"step_per_metre", &rp.stepPerMetre, "[0, 10]", "m/m", "... plus this per metre between them"},
        {"max_camber", &rp.maxCamber, "[0, 0.5]", "m/m", "the road's cross slope up to this is taken out before the step test"},
        {"max_gap", &rp.maxGap, "(0, 1000]", "m", "a longer gap along a ring ends its walk"},
        {"window", &rp.window, "[0, 1000]", "m", "the step test looks this far back along the walk"},
        {"gutter_rise", &rp.gutterRise, "[0, 10]", "m", "a rise this high out of the gutter ends the road without a kerb (0: off)"},
        {"seed_half_width", &rp.seedHalfWidth, "(0, 100]", "m", "walks start from ground points this close to the vehicle's axis ..."},
        {"seed_tolerance", &rp.seedTolerance, "(0, 10]", "m", "... and this close to the road level"}}},
      {"match",
       {{"backend", choice(&mt.backend, {"ndt2d", "pcl"}), "", "", "ndt2d: the 2-D NDT; pcl: PCL's 3-D NDT, the baseline"},
        {"cell_sizes", &mt.cellSizes, "[0.5, 100]", "m", "NDT cell sizes, coarse to fine"},
        {"outlier_ratio", &mt.outlierRatio, "(0, 1)", "", "NDT's outlier share in the score's mixture"},
        {"max_iterations", &mt.maxIterations, "[1, 1000]", "", "Newton iterations per cell size"},
        {"time_budget_ms", &mt.timeBudgetMs, "(0, 1000000]", "ms", "a match taking longer is rejected (eval turns this off)"},
        {"pcl_resolution", &mt.pclResolution, "[0.5, 100]", "m", "voxel size of the pcl backend"},
        {"curb_huber", &mt.curbHuber, "(0, 10]", "m", "robust loss of the curb refinement"},
        {"curb_max_distance", &mt.curbMaxDistance, "(0, 100]", "m", "curb points farther than this from the drivable boundary are ignored"},
        {"min_curb_points", &mt.minCurbPoints, "[1, 100000]", "", "curb points needed for the curb refinement and curb evidence"},
        {"boundary_band", &mt.boundaryBand, "(0, 100]", "m", "points this close to the drivable boundary constrain its normal"},
        {"degenerate_ratio", &mt.degenerateRatio, "[0, 1)", "", "a direction is observable when its boundary constraint is this share of the strongest ..."},
        {"min_boundary_points", &mt.minBoundaryPoints, "[0, 1000000]", "", "... and at least this many point-equivalents"},
        {"min_information", &mt.minInformation, "[0, 1000000000]", "1/m^2", "... and the NDT information there at least this"},
        {"min_points", &mt.minPoints, "[1, 10000000]", "", "a match needs this many road points"},
        {"min_inlier_ratio", &mt.minInlierRatio, "[0, 1]", "", "share of the road points that must land on the drivable area"},
        {"prediction_sigma", &mt.predictionSigma, "(0, 1000]", "m, m, rad", "the odometry prediction's sigma (x, y, yaw) for the gate"},
        {"gate_chi2", &mt.gateChi2, "(0, 1000000000]", "", "a match farther than this (chi-square, 3 dof) from the prediction is rejected"},
        {"stale_region_size", &mt.staleRegionSize, "[0.5, 1000]", "m", "square regions in which a stale map is looked for"},
        {"stale_distance", &mt.staleDistance, "(0, 1000]", "m", "points this far outside the drivable area at the prediction ..."},
        {"stale_distance_per_metre", &mt.staleDistancePerMetre, "[0, 10]", "m/m", "... plus this per metre of range ..."},
        {"stale_share", &mt.staleShare, "[0, 1]", "", "... for more than this share of a region's points: the region is left out"},
        {"evidence_share", &mt.evidenceShare, "[0, 1)", "", "poses are allowed while at most this share of the points leave the drivable area ..."},
        {"evidence_min_points", &mt.evidenceMinPoints, "[0, 1000000]", "", "... or this many"},
        {"evidence_margin", &mt.evidenceMargin, "[-10, 10]", "m", "a point counts as off beyond this past the boundary"},
        {"evidence_curb_band", &mt.evidenceCurbBand, "(0, 10]", "m", "curb points count as off this far from the boundary"},
        {"evidence_curb_share", &mt.evidenceCurbShare, "[0, 1)", "", "share of the curb points that may leave"},
        {"evidence_stride", &mt.evidenceStride, "[1, 1000]", "", "every n-th road point is counted (speed)"},
        {"evidence_max_offset", &mt.evidenceMaxOffset, "(0, 100]", "m", "the evidence search's extent along and across the heading ..."},
        {"evidence_max_yaw_deg", &mt.evidenceMaxYawDeg, "(0, 90]", "deg", "... and in yaw; beyond it a direction is unbounded"},
        {"evidence_kappa", &mt.evidenceKappa, "(0, 100]", "", "a direction's sigma is the allowed half-width / kappa"},
        {"map_sigma", &mt.mapSigma, "[0, 10]", "m", "the drivable polygon's own error"},
        {"map_sigma_yaw_deg", &mt.mapSigmaYawDeg, "[0, 10]", "deg", "the same in yaw"},
        {"max_sigma_along", &mt.maxSigmaAlong, "(0, 1000000]", "m", "a less certain along-track direction is reported unobservable"},
        {"max_sigma_lateral", &mt.maxSigmaLateral, "(0, 1000000]", "m", "the same across the road"},
        {"max_sigma_yaw_deg", &mt.maxSigmaYawDeg, "(0, 1000000]", "deg", "the same in yaw"}}},
      {"prior",
       {{"altitude_sigma", &p.altitudeSigma, "(0, 100]", "m", "the ground-height raster's accuracy: the altitude prior's sigma"},
        {"along_track_sigma", &p.alongTrackSigma, "[0, 1000]", "m", "added to a prior's sigma along the heading (junction matches are biased there)"},
        {"innovation_gate_probability", &p.innovationGateProbability, "[0, 1)", "", "a prior enters the graph only inside this chi-square quantile of its innovation (0: all)"},
        {"reanchor_priors", &p.reanchorPriors, "[0, 1000]", "", "this many gated priors agreeing with one another re-anchor the gate (0: never)"}}},
      {"graph",
       {{"prior_huber", &gr.priorHuber, "(0, 1000000]", "", "Huber loss on the prior residuals, whitened"},
        {"max_iterations", &gr.maxIterations, "[1, 10000]", "", "Ceres iterations per solve"},
        {"odometry_translation_sigma_per_m", &gr.odometryTranslationSigmaPerM, "(0, 10]", "m/m", "the built-in odometry's drift model, per metre travelled"},
        {"odometry_rotation_sigma_deg_per_m", &gr.odometryRotationSigmaDegPerM, "(0, 180]", "deg/m", "the same in rotation"},
        {"given_odometry_translation_sigma_per_m", &gr.givenOdometryTranslationSigmaPerM, "(0, 10]", "m/m", "the drift model of a trajectory file (run --odometry)"},
        {"given_odometry_rotation_sigma_deg_per_m", &gr.givenOdometryRotationSigmaDegPerM, "(0, 180]", "deg/m", "the same in rotation"},
        {"map_error_length", &gr.mapErrorLength, "[0, 1000000]", "m", "the map's error is correlated along the route over this (0: independent per prior)"},
        {"drift_model_margin_nats", &gr.driftModelMarginNats, "[0, 1000000]", "nats", "the final solve takes the tightest drift model this close to the likeliest"}}},
      {"sweeps",
       {{"max_unreadable_share", &c.maxUnreadableSweepShare, "[0, 1]", "", "unreadable sweeps are skipped; more than this share fails the log"}}},
  };
}

// The JSON path of a field: "match.min_points".
std::string keyOf(const Section& s, const Field& f) { return s.path + "." + f.key; }

template <class T>
T numberIn(const Field& f, const json& v, const std::string& key, const std::string& source) {
  const double d = std::is_same_v<T, int> ? double(json_reading::integer(v, key, source)) : json_reading::number(v, key, source);
  if (!Range(f.range).contains(d)) throw Error(source, key + " = " + v.dump() + " is out of range " + f.range);
  return T(d);
}

std::vector<double> arrayIn(const Field& f, const json& v, const std::string& key, const std::string& source) {
  if (!v.is_array() || v.empty()) throw Error(source, key + " must be a non-empty array of numbers");
  std::vector<double> out;
  for (const json& e : v) out.push_back(numberIn<double>(f, e, key, source));
  return out;
}

std::string namesOf(const Choice& c, const char* separator) {
  std::string names;
  for (const char* n : c.names) names += std::string(names.empty() ? "" : separator) + n;
  return names;
}

void setField(const Field& f, const json& v, const std::string& key, const std::string& source) {
  struct Setter {
    const Field& f;
    const json& v;
    const std::string& key;
    const std::string& source;
    void operator()(int* p) const { *p = numberIn<int>(f, v, key, source); }
    void operator()(double* p) const { *p = numberIn<double>(f, v, key, source); }
    void operator()(std::vector<double>* p) const { *p = arrayIn(f, v, key, source); }
    void operator()(Eigen::Vector3d* p) const {
      const std::vector<double> a = arrayIn(f, v, key, source);
      if (a.size() != 3) throw Error(source, key + " must be an array of 3 numbers");
      *p = {a[0], a[1], a[2]};
    }
    void operator()(const Choice& c) const {
      for (size_t i = 0; i < c.names.size(); ++i) {
        if (v.is_string() && v.get<std::string>() == c.names[i]) return c.set(i);
      }
      throw Error(source, key + " must be one of " + namesOf(c, ", "));
    }
  };
  std::visit(Setter{f, v, key, source}, f.value);
}

struct Getter {
  json operator()(const Eigen::Vector3d* p) const { return {p->x(), p->y(), p->z()}; }
  json operator()(const Choice& c) const { return c.names.at(c.get()); }
  json operator()(const auto* p) const { return *p; }
};

json valueOf(const Field& f) { return std::visit(Getter{}, f.value); }

const Section* sectionAt(const std::vector<Section>& schema, const std::string& path) {
  for (const Section& s : schema) {
    if (s.path == path) return &s;
  }
  return nullptr;
}

const Field* fieldAt(const Section* section, const std::string& key) {
  if (!section) return nullptr;
  for (const Field& f : section->fields) {
    if (key == f.key) return &f;
  }
  return nullptr;
}

bool isSectionPrefix(const std::vector<Section>& schema, const std::string& path) {
  return std::any_of(schema.begin(), schema.end(), [&](const Section& s) { return s.path == path || s.path.starts_with(path + "."); });
}

void readObject(const json& obj, const std::string& path, const std::vector<Section>& schema, const std::string& source) {
  if (!obj.is_object()) throw Error(source, (path.empty() ? std::string("the file") : path) + " must be a JSON object");
  for (const auto& [key, value] : obj.items()) {
    const std::string full = path.empty() ? key : path + "." + key;
    if (isSectionPrefix(schema, full)) {
      readObject(value, full, schema, source);
      continue;
    }
    const Field* field = fieldAt(sectionAt(schema, path), key);
    if (!field) throw Error(source, "unknown key " + full);
    setField(*field, value, full, source);
  }
}

// The checks that span keys.
void checkAcrossKeys(const Config& c, const std::string& source) {
  if (c.odometry.features.minRange >= c.odometry.features.maxRange) {
    throw Error(source, "odometry.features.min_range must be below odometry.features.max_range");
  }
  if (!std::is_sorted(c.match.cellSizes.rbegin(), c.match.cellSizes.rend())) {
    throw Error(source, "match.cell_sizes must go from coarse to fine (decreasing)");
  }
}

Config parseOnto(Config c, const std::string& text, const std::string& source) {
  readObject(json_reading::parse(text, source), "", schemaOf(c), source);
  setEgoHeight(c, c.prior.egoHeight);
  checkAcrossKeys(c, source);
  return c;
}

std::string rangeOf(const Field& f) {
  if (const Choice* c = std::get_if<Choice>(&f.value)) return namesOf(*c, " | ");
  return f.range;
}

}  // namespace

void setEgoHeight(Config& config, double egoHeight) {
  config.prior.egoHeight = egoHeight;
  config.roadPoints.ground.groundZ = -egoHeight;
  config.roadPoints.road.groundZ = -egoHeight;
}

const Config& defaultConfig() {
  static const Config config = parseOnto(Config{}, "{}", "the built-in configuration");
  return config;
}

Config parseConfig(const std::string& text, const std::string& source) { return parseOnto(defaultConfig(), text, source); }

std::string formatConfig(const Config& config) {
  Config c = config;
  json root = json::object();
  for (const Section& s : schemaOf(c)) {
    for (const Field& f : s.fields) {
      std::string pointer = "/" + keyOf(s, f);
      std::replace(pointer.begin(), pointer.end(), '.', '/');
      root[json::json_pointer(pointer)] = valueOf(f);
    }
  }
  return root.dump(2) + "\n";
}

Config loadConfig(const std::filesystem::path& path) { return parseConfig(readFileText(path), path.string()); }

void saveConfig(const std::filesystem::path& path, const Config& config) { writeFileAtomically(path, formatConfig(config)); }

std::vector<ConfigKey> configKeys() {
  Config c = defaultConfig();
  std::vector<ConfigKey> keys;
  for (const Section& s : schemaOf(c)) {
    for (const Field& f : s.fields) keys.push_back({keyOf(s, f), valueOf(f).dump(), rangeOf(f), f.unit, f.description});
  }
  return keys;
}

}  // namespace hdprior
