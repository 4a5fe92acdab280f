#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "engine/changes/map_change_report.h"
#include "render/analysis.h"
#include "render/layer_registry.h"
#include "ui/layer_visibility.h"

namespace hdprior::test {
namespace {

// Every layer, as the app builds them (no GL needed until a scene is set).
ui::LayerVisibility::Layers allLayers() {
  ui::LayerVisibility::Layers layers;
  for (const std::string& name : render::layerNames()) layers.push_back(render::makeLayer(name));
  return layers;
}

std::vector<std::string> visibleNames(const ui::LayerVisibility::Layers& layers) {
  std::vector<std::string> names;
  for (const auto& layer : layers)
    if (layer->visible) names.push_back(layer->name());
  std::sort(names.begin(), names.end());
  return names;
}

render::Layer& named(const ui::LayerVisibility::Layers& layers, const std::string& name) {
  return **std::find_if(layers.begin(), layers.end(), [&](const auto& l) { return l->name() == name; });
}

PoseTrajectory onePose() { return PoseTrajectory({0}, {SE3::Identity()}); }

// What a pipeline run and a matched keyframe hand the app.
render::Analysis fullAnalysis() {
  render::Analysis analysis;
  analysis.odometry = onePose();
  analysis.optimized = onePose();
  analysis.file = onePose();
  analysis.keyframes.push_back({});
  analysis.inspection.emplace();
  analysis.landscape.emplace();
  analysis.comparison = render::Comparison{.name = "b", .optimized = onePose()};
  analysis.comparison->inspection.emplace();
  analysis.measure.emplace();
  analysis.changes = std::make_shared<const MapChangeReport>();
  return analysis;
}

TEST(LayerVisibility, StartsWithTheDefaultSetOnly) {
  const auto layers = allLayers();
  ui::LayerVisibility visibility;
  visibility.reset(layers);
  EXPECT_EQ(visibleNames(layers),
            (std::vector<std::string>{"boundary", "drivable", "ego", "ground", "sweep", "trajectory"}));
}

TEST(LayerVisibility, ShowsAnAnalysisLayerWhenItsDataFirstArrives) {
  const auto layers = allLayers();
  ui::LayerVisibility visibility;
  visibility.reset(layers);
  visibility.analysisArrived(layers, render::Analysis{});  // nothing computed yet
  EXPECT_FALSE(named(layers, "keyframes").visible);

  render::Analysis run;  // a run: trajectories and keyframes, no keyframe inspected
  run.odometry = onePose();
  run.keyframes.push_back({});
  visibility.analysisArrived(layers, run);
  EXPECT_TRUE(named(layers, "odometry_trajectory").visible);
  EXPECT_TRUE(named(layers, "keyframes").visible);
  EXPECT_FALSE(named(layers, "match").visible);

  visibility.analysisArrived(layers, fullAnalysis());
  for (const std::string& name : render::layerNames()) {
    if (render::needsAnalysis(name)) {
      EXPECT_TRUE(named(layers, name).visible) << name;
    }
  }
  EXPECT_FALSE(named(layers, "accumulated").visible);  // extras stay as they were
}

// Opening a trajectory file shows its layer at once, before any run.
TEST(LayerVisibility, ShowsTheFileTrajectoryWhenAFileIsOpened) {
  const auto layers = allLayers();
  ui::LayerVisibility visibility;
  visibility.reset(layers);
  render::Analysis opened;
  opened.file = onePose();
  visibility.analysisArrived(layers, opened);
  EXPECT_TRUE(named(layers, "file_trajectory").visible);
  EXPECT_FALSE(named(layers, "odometry_trajectory").visible);
}

TEST(LayerVisibility, ArrivingDataNeverOverridesTheUser) {
  const auto layers = allLayers();
  ui::LayerVisibility visibility;
  visibility.reset(layers);
  visibility.setByUser(named(layers, "match"), false);  // hidden before its data arrived
  visibility.analysisArrived(layers, fullAnalysis());
  EXPECT_FALSE(named(layers, "match").visible);
  EXPECT_TRUE(named(layers, "keyframes").visible);

  visibility.setByUser(named(layers, "keyframes"), false);  // hidden after its data arrived
  visibility.analysisArrived(layers, fullAnalysis());
  EXPECT_FALSE(named(layers, "keyframes").visible);

  visibility.reset(layers);  // a newly opened log starts over
  visibility.analysisArrived(layers, fullAnalysis());
  EXPECT_TRUE(named(layers, "match").visible);
}

}  // namespace
}  // namespace hdprior::test
