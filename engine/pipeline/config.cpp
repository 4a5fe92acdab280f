#include "engine/pipeline/config.h"

#include <limits>
#include <map>
#include <variant>
#include <vector>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"

namespace hdprior {
namespace {

using nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Field {
  const char* key;
  std::variant<int*, double*, bool*, std::string*> value;
  double lo = -kInf, hi = kInf;  // inclusive range of numbers
};
using Sections = std::map<std::string, std::vector<Field>>;  // section path -> its fields

// Every configurable value with its JSON key and allowed range, in one place.
Sections sectionsOf(Config& c) {
  FeatureOptions& f = c.odometry.features;
  RegistrationOptions& r = c.odometry.registration;
  LocalMapOptions& m = c.odometry.localMap;
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
      {"keyframes", {{"distance", &c.keyframes.distance, 0, 100000}, {"rotation_deg", &c.keyframes.rotationDeg, 0, 360}}},
  };
}

std::string rangeText(const Field& f) {
  return "[" + json(f.lo).dump() + ", " + json(f.hi).dump() + "]";
}

void setField(const Field& f, const json& v, const std::string& key, const std::string& source) {
  std::visit(
      [&](auto* p) {
        using T = std::remove_pointer_t<decltype(p)>;
        if constexpr (std::is_same_v<T, bool>) {
          if (!v.is_boolean()) throw Error(source, key + " must be true or false");
          *p = v.get<bool>();
        } else if constexpr (std::is_same_v<T, std::string>) {
          if (!v.is_string()) throw Error(source, key + " must be a string");
          *p = v.get<std::string>();
        } else {
          const double d = std::is_same_v<T, int> ? double(json_reading::integer(v, key, source)) : json_reading::number(v, key, source);
          if (d < f.lo || d > f.hi) throw Error(source, key + " = " + v.dump() + " is out of range " + rangeText(f));
          *p = T(d);
        }
      },
      f.value);
}

void readSection(const json& obj, const std::string& path, const Sections& sections, Config& c, const std::string& source) {
  if (!obj.is_object()) throw Error(source, (path.empty() ? std::string("the file") : path) + " must be a JSON object");
  for (const auto& [key, value] : obj.items()) {
    const std::string full = path.empty() ? key : path + "." + key;
    if (sections.count(full)) {
      readSection(value, full, sections, c, source);
      continue;
    }
    if (path.empty() && (key == "road_points" || key == "match" || key == "graph")) {
      if (!value.is_object()) throw Error(source, key + " must be a JSON object");
      (key == "road_points" ? c.roadPointsJson : key == "match" ? c.matchJson : c.graphJson) = value.dump();
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

}  // namespace

Config parseConfig(const std::string& text, const std::string& source) {
  Config c;
  const Sections sections = sectionsOf(c);
  readSection(json_reading::parse(text, source), "", sections, c, source);
  if (c.odometry.deskew.mode != "none" && c.odometry.deskew.mode != "constant_velocity") {
    throw Error(source, "odometry.deskew.mode must be \"none\" or \"constant_velocity\"");
  }
  if (c.odometry.features.minRange >= c.odometry.features.maxRange) {
    throw Error(source, "odometry.features.min_range must be below max_range");
  }
  return c;
}

std::string formatConfig(const Config& config) {
  Config c = config;
  json root = json::object();
  for (const auto& [path, fields] : sectionsOf(c)) {
    std::string slashPath = "/" + path;
    for (char& ch : slashPath) if (ch == '.') ch = '/';
    json& section = root[json::json_pointer(slashPath)];
    if (section.is_null()) section = json::object();
    for (const Field& f : fields) {
      std::visit([&](auto* p) { section[f.key] = *p; }, f.value);
    }
  }
  root["road_points"] = json::parse(c.roadPointsJson);
  root["match"] = json::parse(c.matchJson);
  root["graph"] = json::parse(c.graphJson);
  return root.dump(2) + "\n";
}

Config loadConfig(const std::filesystem::path& path) { return parseConfig(readFileText(path), path.string()); }

void saveConfig(const std::filesystem::path& path, const Config& config) { writeFileAtomically(path, formatConfig(config)); }

}  // namespace hdprior
