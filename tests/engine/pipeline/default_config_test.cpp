#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <algorithm>
#include <string>
#include <vector>

#include "engine/pipeline/config.h"
#include "engine/pipeline/config_schema.h"
#include "test_data.h"

namespace hdprior {

// The option structs' initialisers are the defaults: the built-in configuration is them, with the
// one ego height set through (vehicle.ego_height also gives the road level of the road points).
TEST(DefaultConfig, IsTheStructInitialisers) {
  EXPECT_EQ(formatConfig(defaultConfig()), formatConfig(Config{}));
  EXPECT_DOUBLE_EQ(Config{}.roadPoints.ground.groundZ, -Config{}.prior.egoHeight);
  EXPECT_DOUBLE_EQ(Config{}.roadPoints.road.groundZ, -Config{}.prior.egoHeight);
}

TEST(DefaultConfig, AFileOverridesOnlyItsKeys) {
  Config expected = defaultConfig();
  expected.keyframes.distance = 3.5;
  EXPECT_EQ(formatConfig(parseConfig(R"({"keyframes": {"distance": 3.5}})", "my.json")), formatConfig(expected));
  EXPECT_EQ(formatConfig(parseConfig("{}", "empty.json")), formatConfig(defaultConfig()));
}

namespace {

// The dotted keys of a configuration's JSON: its leaves (an array is one leaf).
void leafKeys(const nlohmann::json& j, const std::string& path, std::vector<std::string>& out) {
  if (!j.is_object()) return out.push_back(path);
  for (const auto& [key, value] : j.items()) leafKeys(value, path.empty() ? key : path + "." + key, out);
}

}  // namespace

// At most 90 keys, each with a range and a description; the formatted configuration has exactly
// the schema's keys.
TEST(DefaultConfig, EveryKeyIsDescribedAndThereAreAtMost90) {
  const std::vector<ConfigKey> keys = configKeys();
  EXPECT_LE(keys.size(), 90u);
  std::vector<std::string> formatted, schema;
  leafKeys(nlohmann::json::parse(formatConfig(defaultConfig())), "", formatted);
  for (const ConfigKey& k : keys) {
    schema.push_back(k.key);
    EXPECT_FALSE(k.description.empty()) << k.key;
    EXPECT_FALSE(k.range.empty()) << k.key;
  }
  std::sort(schema.begin(), schema.end());
  EXPECT_EQ(formatted, schema);  // nlohmann's objects keep their keys sorted
}

// docs/config.md is the reference as `hdprior config --reference` prints it.
TEST(DefaultConfig, TheReferenceInDocsIsCurrent) {
  EXPECT_EQ(test::readFileText(test::sourceDir() / "docs" / "config.md"), configReference())
      << "regenerate it: build/app/hdprior config --reference > docs/config.md";
}

}  // namespace hdprior
