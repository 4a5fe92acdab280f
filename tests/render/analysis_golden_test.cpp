// Golden images of the analysis layers and the landscape and inspector views: on a short simulated
// town log (generated here, deterministic) and on the real shared log (two sweeps, one keyframe).
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include <unistd.h>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/session.h"
#include "engine/sim/log_writer.h"
#include "render/analysis.h"
#include "render/image_compare.h"
#include "render/layer_registry.h"
#include "render/snapshot.h"
#include "test_data.h"

namespace hdprior::test {
namespace {

// The default configuration without the matcher's time budget: a match cut short on a busy
// machine would change the picture.
Config untimedConfig() {
  Config config;
  config.match.timeBudgetMs = 1e6;
  return config;
}

// A log, its prior map and the analysis of one run over it with keyframe `keyframe` inspected.
struct AnalysedLog {
  std::unique_ptr<ArgoverseLog> log;
  std::unique_ptr<HdMap> map;
  render::Analysis analysis;

  AnalysedLog(const std::filesystem::path& dir, size_t keyframe) : log(std::make_unique<ArgoverseLog>(dir)) {
    map = loadPriorMap(*log, untimedConfig());
    Session session(*log, map.get(), untimedConfig());
    session.run();
    session.optimize();
    analysis = render::analysisOf(session);
    render::inspect(analysis, session, *map, keyframe);
  }

  render::Image snapshot(render::View view, const std::string& layers, bool overlay = true) const {
    render::SnapshotOptions options{640, 360, view, layers.empty() ? std::vector<std::string>{} : render::parseLayerList(layers),
                                    overlay, {}};
    render::Snapshotter snapshotter(*log, *map, options);
    snapshotter.setAnalysis(analysis);
    return snapshotter.render(analysis.inspection->frame);
  }
};

bool updatingGoldens() {
  const char* update = std::getenv("HDPRIOR_UPDATE_GOLDEN");
  return update && std::string(update) == "1";
}

constexpr const char* kTopLayers =
    "drivable,boundary,ndt_cells,trajectory,odometry_trajectory,optimized_trajectory,keyframes,road_points,match,ego";

class AnalysisGolden : public ::testing::Test {
 protected:
  // A 4 s drive through a procedural town (40 sweeps, 14 keyframes); keyframe 7, accepted, is inspected.
  static const AnalysedLog& simulated() {
    static const AnalysedLog log = [] {
      SimulationOptions sim;
      sim.townSeed = 2;
      sim.seed = 3;
      sim.seconds = 4.0;
      sim.outDir = processOutputDir("analysis_golden");
      return AnalysedLog(simulateLog(sim).dir, 7);
    }();
    return log;
  }
  static const AnalysedLog& real() {
    static const AnalysedLog log(sharedLog(), 0);
    return log;
  }
};

TEST_F(AnalysisGolden, SimulatedTopAnalysisLayers) {
  EXPECT_EQ(checkGolden(simulated().snapshot(render::View::Top, kTopLayers), "sim_top_analysis"), "");
}

TEST_F(AnalysisGolden, SimulatedLandscapeView) {
  EXPECT_EQ(checkGolden(simulated().snapshot(render::View::Landscape, ""), "sim_landscape_view"), "");
}

TEST_F(AnalysisGolden, SimulatedInspectorView) {
  EXPECT_EQ(checkGolden(simulated().snapshot(render::View::Inspector, ""), "sim_inspector_view"), "");
}

TEST_F(AnalysisGolden, RealLandscapeView) {
  EXPECT_EQ(checkGolden(real().snapshot(render::View::Landscape, ""), "real_landscape_view"), "");
}

TEST_F(AnalysisGolden, RealTopRoadPointsAndMatch) {
  EXPECT_EQ(checkGolden(real().snapshot(render::View::Top, "drivable,boundary,keyframes,road_points,match,ego"),
                        "real_top_road_points_match"), "");
}

// The comparison has teeth for the new layers: the landscape view without its heat map, or the
// top view without the road points, must fail against their goldens.
TEST_F(AnalysisGolden, FailsWhenAnAnalysisLayerIsSwitchedOff) {
  if (updatingGoldens()) GTEST_SKIP() << "regenerating goldens";
  const std::string noLandscape =
      checkGolden(real().snapshot(render::View::Landscape, "drivable,boundary,road_points,match"), "real_landscape_view");
  EXPECT_NE(noLandscape.find("differ"), std::string::npos) << noLandscape;
  const std::string noPoints =
      checkGolden(real().snapshot(render::View::Top, "drivable,boundary,keyframes,match,ego"), "real_top_road_points_match");
  EXPECT_NE(noPoints.find("differ"), std::string::npos) << noPoints;
}

// The goldens show the overlay: the landscape view's colour bar, scale bar and marker legend. Without
// them the same view fails against its golden, and the bar's corner holds Turbo's blue and red.
TEST_F(AnalysisGolden, GoldensShowTheColourBarScaleBarAndLegend) {
  if (updatingGoldens()) GTEST_SKIP() << "regenerating goldens";
  const std::string bare = checkGolden(real().snapshot(render::View::Landscape, "", false), "real_landscape_view");
  EXPECT_NE(bare.find("differ"), std::string::npos) << bare;
  const render::Image golden = readPng(std::filesystem::path(HDPRIOR_GOLDEN_DIR) / "real_landscape_view.png");
  size_t blue = 0, red = 0;  // Turbo's ends, in the bottom-right quarter where the colour bar sits
  for (int y = golden.height * 3 / 4; y < golden.height; ++y)
    for (int x = golden.width * 3 / 4; x < golden.width; ++x) {
      const uint8_t* p = golden.pixel(x, y);
      blue += p[2] > 150 && p[0] < 90 && p[1] < 120;
      red += p[0] > 120 && p[1] < 60 && p[2] < 40;
    }
  EXPECT_GT(blue, 20u);
  EXPECT_GT(red, 20u);
}

TEST_F(AnalysisGolden, AnalysisHoldsPerPoseErrorsAndKeyframesAndRefusesABadKeyframe) {
  const AnalysedLog& r = real();
  Session session(*r.log, r.map.get(), untimedConfig());
  session.run();
  render::Analysis analysis = render::analysisOf(session);
  ASSERT_EQ(analysis.odometry.size(), r.log->sweepCount());
  ASSERT_EQ(analysis.odometryError.size(), analysis.odometry.size());
  EXPECT_LT(analysis.odometryError.front(), 1e-6);  // the run starts at the first true pose
  EXPECT_LT(analysis.odometryError.back(), 0.5);
  EXPECT_EQ(analysis.keyframes.size(), session.odometry().keyframes().size());
  EXPECT_EQ(analysis.keyframes.front().frame, 0u);
  EXPECT_THROW(render::inspect(analysis, session, *r.map, analysis.keyframes.size()), Error);
  // The simulated drive's keyframes have match statuses and the optimised trajectory its errors.
  const render::Analysis& sim = simulated().analysis;
  ASSERT_GT(sim.keyframes.size(), 2u);
  EXPECT_TRUE(sim.keyframes.back().constraint.has_value());
  EXPECT_EQ(sim.optimizedError.size(), sim.optimized.size());
  EXPECT_FALSE(sim.landscape->scores.empty());
}

}  // namespace
}  // namespace hdprior::test
