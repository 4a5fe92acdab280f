#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "engine/pipeline/config.h"
#include "engine/pipeline/config_schema.h"
#include "test_data.h"

namespace hdprior::test {
namespace {

void write(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

TEST(ConfigCommand, DefaultsPrintsEveryKeyAndChecksAsValid) {
  const CommandResult r = runHdprior("config --defaults");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, formatConfig(defaultConfig()));
  EXPECT_EQ(formatConfig(parseConfig(r.out, "defaults")), r.out);
  const std::filesystem::path file = freshOutputDir("config_defaults") / "defaults.json";
  write(file, r.out);
  const CommandResult check = runHdprior("config --check '" + file.string() + "'");
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(check.out, file.string() + ": a valid configuration\n");
}

// The same one-line errors as every command that reads a configuration.
TEST(ConfigCommand, CheckNamesTheFileAndTheKeyInOneLine) {
  const std::filesystem::path dir = freshOutputDir("config_check");
  const struct {
    const char* name;
    const char* text;
    const char* message;
  } cases[] = {
      {"unknown.json", R"({"match": {"outlier": 0.5}})", "unknown.json: unknown key match.outlier"},
      {"range.json", R"({"match": {"outlier_ratio": 7}})", "range.json: match.outlier_ratio = 7 is out of range (0, 1)"},
      {"stage.json", R"({"match": {"min_points": 0}})", "stage.json: match.min_points = 0 is out of range [1, 10000000]"},
      {"dropped.json", R"({"road_points": {"submap": true}})", "dropped.json: unknown key road_points.submap"},
      {"type.json", R"({"keyframes": {"distance": "far"}})", "type.json: keyframes.distance"},
      {"broken.json", R"({"keyframes": )", "broken.json: invalid JSON"},
  };
  for (const auto& c : cases) {
    write(dir / c.name, c.text);
    const CommandResult r = runHdprior("config --check '" + (dir / c.name).string() + "'");
    EXPECT_EQ(r.status, 2) << c.name;
    EXPECT_EQ(r.err.rfind("hdprior config: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const CommandResult missing = runHdprior("config --check '" + (dir / "none.json").string() + "'");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
}

TEST(ConfigCommand, ReferencePrintsDocsConfigMd) {
  const CommandResult r = runHdprior("config --reference");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, configReference());
  EXPECT_NE(r.out.find("| `match.min_points` | `200` | [1, 10000000] |"), std::string::npos);
}

TEST(ConfigCommand, NeedsExactlyOneOfDefaultsReferenceAndCheck) {
  const CommandResult none = runHdprior("config");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("give exactly one of --defaults, --reference and --check FILE"), std::string::npos) << none.err;
  const CommandResult both = runHdprior("config --defaults --check x.json");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("option --defaults: cannot be combined with --check"), std::string::npos) << both.err;
}

}  // namespace
}  // namespace hdprior::test
