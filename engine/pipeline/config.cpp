#include "engine/pipeline/config.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"
#include "engine/pipeline/config_schema.h"

namespace hdprior {
namespace {

using nlohmann::json;

struct Section {
  std::string path;
  std::vector<OptionField> fields;
};

// The schema: every key of the configuration, once, bound to the member of `c` that holds it (the
// stages declare their own keys next to their options: optionFields). A member's initialiser is the
// key's default.
std::vector<Section> schemaOf(Config& c) {
  return {
      {"vehicle",
       {{"ego_height", &c.prior.egoHeight, "[0, 10]", "m", "height of the ego origin above the road surface (Argoverse 2: 0.32)"}}},
      {"odometry.features", optionFields(c.odometry.features)},
      {"odometry.deskew", optionFields(c.odometry.deskew)},
      {"odometry.registration", optionFields(c.odometry.registration)},
      {"odometry.local_map", optionFields(c.odometry.localMap)},
      {"keyframes", optionFields(c.keyframes)},
      {"road_points", optionFields(c.roadPoints)},
      {"road_points.ground", optionFields(c.roadPoints.ground)},
      {"road_points.road", optionFields(c.roadPoints.road)},
      {"match", optionFields(c.match)},
      {"prior", optionFields(c.prior)},
      {"graph", optionFields(c.graph)},
      {"sweeps",
       {{"max_unreadable_share", &c.maxUnreadableSweepShare, "[0, 1]", "", "unreadable sweeps are skipped; more than this share fails the log"}}},
  };
}

// The JSON path of a field: "match.min_points".
std::string keyOf(const Section& s, const OptionField& f) { return s.path + "." + f.key; }

template <class T>
T numberIn(const OptionField& f, const json& v, const std::string& key, const std::string& source) {
  const double d = std::is_same_v<T, int> ? double(json_reading::integer(v, key, source)) : json_reading::number(v, key, source);
  if (!OptionRange(f.range).contains(d)) throw Error(source, key + " = " + v.dump() + " is out of range " + f.range);
  return T(d);
}

std::vector<double> arrayIn(const OptionField& f, const json& v, const std::string& key, const std::string& source) {
  if (!v.is_array() || v.empty()) throw Error(source, key + " must be a non-empty array of numbers");
  std::vector<double> out;
  for (const json& e : v) out.push_back(numberIn<double>(f, e, key, source));
  return out;
}

std::string namesOf(const OptionChoice& c, const char* separator) {
  std::string names;
  for (const char* n : c.names) names += std::string(names.empty() ? "" : separator) + n;
  return names;
}

void setField(const OptionField& f, const json& v, const std::string& key, const std::string& source) {
  struct Setter {
    const OptionField& f;
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
    void operator()(const OptionChoice& c) const {
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
  json operator()(const OptionChoice& c) const { return c.names.at(c.get()); }
  json operator()(const auto* p) const { return *p; }
};

json valueOf(const OptionField& f) { return std::visit(Getter{}, f.value); }

const Section* sectionAt(const std::vector<Section>& schema, const std::string& path) {
  for (const Section& s : schema) {
    if (s.path == path) return &s;
  }
  return nullptr;
}

const OptionField* fieldAt(const Section* section, const std::string& key) {
  if (!section) return nullptr;
  for (const OptionField& f : section->fields) {
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
    const OptionField* field = fieldAt(sectionAt(schema, path), key);
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

std::string rangeOf(const OptionField& f) {
  if (const OptionChoice* c = std::get_if<OptionChoice>(&f.value)) return namesOf(*c, " | ");
  return f.range;
}

}  // namespace

void setEgoHeight(Config& config, double egoHeight) {
  config.prior.egoHeight = egoHeight;
  config.roadPoints.ground.groundZ = -egoHeight;
  config.roadPoints.road.groundZ = -egoHeight;
}

void checkConfig(const Config& config) {
  Config c = config;
  for (const Section& s : schemaOf(c)) {
    try {
      checkOptionRanges(s.path, s.fields);
    } catch (const Error& e) {
      throw Error("configuration", s.path + "." + e.reason());
    }
  }
  checkAcrossKeys(c, "configuration");
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
    for (const OptionField& f : s.fields) {
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
    for (const OptionField& f : s.fields) keys.push_back({keyOf(s, f), valueOf(f).dump(), rangeOf(f), f.unit, f.description});
  }
  return keys;
}

}  // namespace hdprior
