#include <gtest/gtest.h>

#include <filesystem>

#include "display_run.h"
#include "engine/error.h"
#include "engine/pipeline/config.h"
#include "test_data.h"
#include "ui/view_session.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

TEST(ViewSession, WritesAndReadsBackEveryField) {
  ui::ViewSession s;
  s.log = "/data/log one";
  s.frame = 42;
  s.camera = {.topDown = true, .followEgo = false, .target = {100.5, -20.25, 3.0}, .yaw = 0.3, .pitch = 0.8, .distance = 33, .topHeight = 55};
  s.layers = {{"sweep", true, 0.5f}, {"lanes", false, 1.0f}};
  s.tab = "Compare";
  s.plots = {"score", "chi2"};
  s.bookmarks = {{7, "kerb"}, {9, ""}};
  s.config = formatConfig(defaultConfig());
  s.ran = true;
  s.keyframe = 5;
  Config b = defaultConfig();
  b.match.outlierRatio = 0.3;
  s.comparison = ui::ViewSession::Comparison{"b.json", formatConfig(b), fs::path("/x/b.json")};
  const fs::path file = freshOutputDir("view_session_roundtrip") / "s.json";
  ui::writeViewSession(file, s);
  const ui::ViewSession r = ui::readViewSession(file);
  EXPECT_EQ(r.log, s.log);
  EXPECT_EQ(r.frame, 42u);
  EXPECT_TRUE(r.camera.topDown);
  EXPECT_FALSE(r.camera.followEgo);
  EXPECT_EQ(r.camera.target, s.camera.target);
  EXPECT_EQ(r.camera.topHeight, 55);
  ASSERT_EQ(r.layers.size(), 2u);
  EXPECT_EQ(r.layers[0].opacity, 0.5f);
  EXPECT_FALSE(r.layers[1].visible);
  EXPECT_EQ(r.tab, "Compare");
  EXPECT_EQ(r.plots, s.plots);
  ASSERT_EQ(r.bookmarks.size(), 2u);
  EXPECT_EQ(r.bookmarks[0].note, "kerb");
  EXPECT_EQ(r.bookmarks[1].frame, 9u);
  EXPECT_EQ(parseConfig(r.config, "a").match.outlierRatio, defaultConfig().match.outlierRatio);
  EXPECT_TRUE(r.ran);
  EXPECT_EQ(r.keyframe, std::optional<size_t>(5));
  ASSERT_TRUE(r.comparison.has_value());
  EXPECT_EQ(parseConfig(r.comparison->config, "b").match.outlierRatio, 0.3);
  EXPECT_EQ(r.comparison->file, std::optional<fs::path>("/x/b.json"));
}

TEST(ViewSession, ABadFileIsOneErrorNamingIt) {
  const fs::path dir = freshOutputDir("view_session_bad");
  EXPECT_THROW(ui::readViewSession(dir / "missing.json"), Error);
  for (const auto& [name, text] : {std::pair{"empty.json", ""}, {"text.json", "not json"}, {"array.json", "[1, 2]"},
                                   {"version.json", "{\"hdprior_view_session\": 7}"},
                                   {"partial.json", "{\"hdprior_view_session\": 1, \"log\": \"x\", \"frame\": 0}"},
                                   {"type.json", "{\"hdprior_view_session\": 1, \"log\": \"x\", \"frame\": \"zero\"}"}}) {
    writeText(dir / name, text);
    try {
      ui::readViewSession(dir / name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace hdprior::test
