#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/error.h"
#include "engine/graph/pose_graph.h"
#include "engine/io/argoverse_log.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"
#include "engine/odom/odometry.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/config_schema.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/prior_stage.h"
#include "test_data.h"

namespace hdprior {
namespace {

using nlohmann::json;

// The ends of a key's range as the schema states it ("(0, 1]": the least number above 0, and 1),
// or each name a choice allows; arrays get one element (three for a vector of three).
std::vector<json> endsOf(const ConfigKey& k) {
  std::vector<json> values;
  if (k.range.front() != '[' && k.range.front() != '(') {
    for (size_t at = 0; at < k.range.size();) {
      const size_t bar = k.range.find(" | ", at);
      values.push_back(k.range.substr(at, bar - at));
      at = bar == std::string::npos ? k.range.size() : bar + 3;
    }
    return values;
  }
  const json def = json::parse(k.defaultValue);
  const bool integer = (def.is_array() ? def[0] : def).is_number_integer();
  char* end = nullptr;
  double lo = std::strtod(k.range.c_str() + 1, &end);
  double hi = std::strtod(end + 1, &end);
  if (k.range.front() == '(') lo = integer ? lo + 1 : std::nextafter(lo, hi);
  if (*end == ')') hi = integer ? hi - 1 : std::nextafter(hi, lo);
  for (double v : {lo, hi}) {
    const json value = integer ? json(int64_t(v)) : json(v);
    values.push_back(def.is_array() ? json(std::vector<json>(def.size(), value)) : value);
  }
  return values;
}

json fileWith(const std::string& key, const json& value) {
  std::string pointer = "/" + key;
  for (char& c : pointer) if (c == '.') c = '/';
  json file = json::object();
  file[json::json_pointer(pointer)] = value;
  return file;
}

// What `run`, `match` and `view` make of a configuration on the real log: the map with the
// configuration's NDT grids, the prior stage (matcher, graph, gate), the odometry's first sweep,
// the road points of a sweep and a match of them.
void buildEveryStage(const ArgoverseLog& log, const Config& c) {
  static std::vector<double> loadedSizes;
  static std::unique_ptr<HdMap> map;
  if (!map || loadedSizes != c.match.cellSizes) {
    map = loadPriorMap(log, c);
    loadedSizes = c.match.cellSizes;
  }
  const SE3 truth = log.cityTEgo().at(log.sweepTimestamps().front());
  PriorStage stage(*map, c, truth);
  Odometry odometry(c.odometry, c.keyframes);
  odometry.registerSweep(*log.sweep(0));  // features and the local map (the first sweep is not registered)
  const std::vector<Eigen::Vector2d> road = sweepRoadPoints(*log.sweep(0), Eigen::Matrix3d::Identity(), c.roadPoints).road;
  MapMatcher matcher(*map, c.match);
  const Eigen::Vector3d start(truth.translation().x(), truth.translation().y(),
                              std::atan2(truth.rotation()(1, 0), truth.rotation()(0, 0)));
  matcher.match(road, start);
}

// Values just beyond each end of a declared range (none for a choice).
std::vector<double> beyondEnds(const OptionField& f) {
  if (std::holds_alternative<OptionChoice>(f.value)) return {};
  const OptionRange r(f.range);
  return {r.loOpen ? r.lo : r.lo - 1, r.hiOpen ? r.hi : r.hi + 1};
}

struct SetTo {
  double v;
  void operator()(int* p) const { *p = int(v); }
  void operator()(double* p) const { *p = v; }
  void operator()(std::vector<double>* p) const { std::fill(p->begin(), p->end(), v); }
  void operator()(Eigen::Vector3d* p) const { p->setConstant(v); }
  void operator()(const OptionChoice&) const {}
};

// Every declared key of Options, set just beyond each end of its range, makes `build` throw an Error
// that names the key and the value.
template <class Options>
void expectEveryKeyRefused(const std::string& stage, const std::function<void(const Options&)>& build) {
  Options declared;
  const std::vector<OptionField> fields = optionFields(declared);
  for (size_t i = 0; i < fields.size(); ++i) {
    for (double v : beyondEnds(fields[i])) {
      Options o;
      std::visit(SetTo{v}, optionFields(o)[i].value);
      const std::string key = fields[i].key;
      try {
        build(o);
        ADD_FAILURE() << stage << " accepted " << key << " = " << v;
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(key + " = "), std::string::npos) << stage << ": " << e.what();
        EXPECT_NE(std::string(e.what()).find(" is out of range " + std::string(fields[i].range)), std::string::npos) << e.what();
      }
    }
  }
}

}  // namespace

// The stages check their options against the same declarations as the configuration file: a value
// the schema refuses is refused by the constructor of the stage that uses it, naming the key, when
// the stage is built in code (the engine's API, the app's sliders) rather than from a file.
TEST(ConfigSchema, EveryRefusedValueIsRefusedByItsStageNamingTheKey) {
  const ArgoverseLog log(test::sharedLog());
  const Config defaults = defaultConfig();
  const std::unique_ptr<HdMap> map = loadPriorMap(log, defaults);
  const SE3 start = log.cityTEgo().at(log.sweepTimestamps().front());
  const auto sweep = log.sweep(0);
  expectEveryKeyRefused<FeatureOptions>("odometry", [&](const FeatureOptions& o) { Odometry({.features = o}, {}); });
  expectEveryKeyRefused<RegistrationOptions>("odometry", [&](const RegistrationOptions& o) { Odometry({.registration = o}, {}); });
  expectEveryKeyRefused<LocalMapOptions>("odometry", [&](const LocalMapOptions& o) { Odometry({.localMap = o}, {}); });
  expectEveryKeyRefused<KeyframeOptions>("odometry", [&](const KeyframeOptions& o) { Odometry({}, o); });
  expectEveryKeyRefused<GroundSegmentationOptions>("road points", [&](const GroundSegmentationOptions& o) {
    labelSweep(*sweep, Eigen::Matrix3d::Identity(), {.ground = o});
  });
  expectEveryKeyRefused<RoadPointOptions>("road points", [&](const RoadPointOptions& o) {
    labelSweep(*sweep, Eigen::Matrix3d::Identity(), {.road = o});
  });
  expectEveryKeyRefused<SweepRoadPointOptions>("road points", [&](const SweepRoadPointOptions& o) {
    sweepRoadPoints(*sweep, Eigen::Matrix3d::Identity(), o);
  });
  expectEveryKeyRefused<MatchOptions>("map matcher", [&](const MatchOptions& o) { MapMatcher(*map, o); });
  expectEveryKeyRefused<PoseGraphOptions>("pose graph", [&](const PoseGraphOptions& o) { PoseGraph{o}; });
  expectEveryKeyRefused<PosePriorOptions>("prior stage", [&](const PosePriorOptions& o) {
    Config c = defaults;
    c.prior = o;
    PriorStage(*map, c, start);
  });
  Config c = defaults;
  setEgoHeight(c, -1);
  try {
    PriorStage(*map, c, start);
    ADD_FAILURE() << "a negative ego height was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "configuration: vehicle.ego_height = -1 is out of range [0, 10]");
  }
}

// No configuration that the schema accepts fails later because of a range: every key at both ends
// of its range (and every name of a choice) builds and runs every stage on the real log.
TEST(ConfigSchema, EveryAcceptedValueBuildsEveryStageOnTheRealLog) {
  const ArgoverseLog log(test::sharedLog());
  int configurations = 0;
  for (const ConfigKey& k : configKeys()) {
    for (const json& value : endsOf(k)) {
      const std::string text = fileWith(k.key, value).dump();
      Config config;
      try {
        config = parseConfig(text, "ends.json");
      } catch (const Error&) {
        continue;  // not accepted: an end that another key's default rules out (min_range against max_range)
      }
      const auto start = std::chrono::steady_clock::now();
      try {
        buildEveryStage(log, config);
      } catch (const std::exception& e) {
        ADD_FAILURE() << text << ": " << e.what();
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_LT(seconds, 5.0) << text << " took " << seconds << " s";
      ++configurations;
    }
  }
  EXPECT_GE(configurations, 2 * 80);
}

}  // namespace hdprior
