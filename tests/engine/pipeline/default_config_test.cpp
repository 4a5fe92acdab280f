#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "engine/pipeline/config.h"

namespace hdprior {
namespace {

using nlohmann::json;

// The keys whose values differ between two configurations' JSON, missing ones included, one a line.
std::string differingKeys(const std::string& expected, const std::string& actual) {
  const json a = json::parse(expected).flatten(), b = json::parse(actual).flatten();
  std::string out;
  for (const auto& [key, value] : a.items()) {
    if (!b.contains(key)) out += key + ": " + value.dump() + " only in the first\n";
    else if (b[key] != value) out += key + ": " + value.dump() + " vs " + b[key].dump() + "\n";
  }
  for (const auto& [key, value] : b.items()) {
    if (!a.contains(key)) out += key + ": " + value.dump() + " only in the second\n";
  }
  return out;
}

}  // namespace

// assets/default_config.json is the one source of the defaults: it names every key, as
// formatConfig writes them.
TEST(DefaultConfig, TheEmbeddedFileNamesEveryKey) {
  const std::string text = defaultConfigText();
  EXPECT_EQ(formatConfig(defaultConfig()), text) << "assets/default_config.json vs the keys hdprior reads:\n"
                                                 << differingKeys(text, formatConfig(defaultConfig()));
}

// The option structs' initialisers (used where code makes an option struct without a configuration)
// must not become a second, different set of defaults. A key added to the configuration fails here
// until assets/default_config.json has it.
TEST(DefaultConfig, TheStructInitialisersEqualTheFile) {
  EXPECT_EQ(formatConfig(Config{}), defaultConfigText())
      << "assets/default_config.json vs the option structs' initialisers (file first; change both):\n"
      << differingKeys(defaultConfigText(), formatConfig(Config{}));
}

// A file sets its keys over the defaults of the embedded file.
TEST(DefaultConfig, AFileOverridesOnlyItsKeys) {
  Config expected = defaultConfig();
  expected.keyframes.distance = 3.5;
  EXPECT_EQ(formatConfig(parseConfig(R"({"keyframes": {"distance": 3.5}})", "my.json")), formatConfig(expected));
  EXPECT_EQ(formatConfig(parseConfig("{}", "empty.json")), defaultConfigText());
}

}  // namespace hdprior
