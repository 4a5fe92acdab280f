// The analysis layers drawn from hand-filled analyses on the real log's map: keyframe markers by
// match status, trajectories coloured by their error, the degenerate match's ellipse clamped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "render/analysis.h"
#include "render/layer_registry.h"
#include "render/offscreen_context.h"
#include "render/renderer.h"
#include "render/snapshot.h"
#include "test_data.h"

namespace hdprior::test {
namespace {

class AnalysisLayers : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    log_ = std::make_unique<ArgoverseLog>(sharedLog());
    map_ = std::make_unique<HdMap>(HdMap::load(log_->mapFiles(), render::renderMapOptions()));
  }
  static void TearDownTestSuite() {
    map_.reset();
    log_.reset();
  }

  // Frame 0 in the top view (80 m tall: 9 px per metre at 1280 x 720), after `adjust` set the
  // layers' options as the app's layers panel does.
  static render::Image draw(const std::string& layers, render::Analysis analysis,
                            const std::function<void(render::Layer&)>& adjust = {}) {
    render::OffscreenContext context(1280, 720);
    render::Renderer renderer;
    renderer.showOverlay = false;  // the layers alone: a colour bar holds every colour of its map
    for (const auto& name : render::parseLayerList(layers)) renderer.addLayer(render::makeLayer(name));
    if (adjust)
      for (const auto& layer : renderer.layers()) adjust(*layer);
    const render::Scene scene = render::makeScene(*log_, *map_);
    renderer.setScene(scene);
    const render::Frame frame = render::makeFrame(scene, 0);
    renderer.setFrame(frame);
    renderer.setAnalysis(std::move(analysis));
    renderer.draw(render::viewCamera(render::View::Top, scene, frame, 1280.0 / 720.0), 1280, 720);
    return context.readPixels();
  }
  // Sets the option labelled `label` of every layer that has one.
  static std::function<void(render::Layer&)> option(const std::string& label, float real, int integer) {
    return [=](render::Layer& layer) {
      for (const render::LayerOption& o : layer.options()) {
        if (o.label != label) continue;
        if (o.real) *o.real = real;
        if (o.integer) *o.integer = integer;
      }
    };
  }
  // A pose `east` / `north` metres from frame 0's.
  static SE3 offsetFromFrame0(double east, double north) {
    SE3 pose = log_->cityTEgo().at(log_->sweepTimestamps()[0]);
    pose.translation() += Eigen::Vector3d(east, north, 0.0);
    return pose;
  }
  static size_t count(const render::Image& image, const std::function<bool(const uint8_t*)>& is) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) n += is(image.pixel(x, y));
    return n;
  }

  static std::unique_ptr<ArgoverseLog> log_;
  static std::unique_ptr<HdMap> map_;
};
std::unique_ptr<ArgoverseLog> AnalysisLayers::log_;
std::unique_ptr<HdMap> AnalysisLayers::map_;

bool colourNear(const uint8_t* p, int r, int g, int b) { return std::abs(p[0] - r) < 12 && std::abs(p[1] - g) < 12 && std::abs(p[2] - b) < 12; }

// Coloured by what the prior fixes (render/constraint_palette.h): full, partial, gated, rejected, none.
TEST_F(AnalysisLayers, KeyframesAreColouredByWhatTheirPriorFixes) {
  using Kind = PriorConstraint::Kind;
  const PriorConstraint full{Kind::Fixes, true, true, true, ""}, lateralYaw{Kind::Fixes, false, true, true, ""},
      gated{Kind::Gated, false, true, true, "chi2 14.2 > 11.3"}, rejected{Kind::Rejected, false, false, false, "too few points"};
  render::Analysis a;
  a.keyframes = {{0, 0, offsetFromFrame0(-20, 0), full},    {1, 1, offsetFromFrame0(-10, 0), lateralYaw},
                 {2, 2, offsetFromFrame0(0, 0), gated},     {3, 3, offsetFromFrame0(10, 0), rejected},
                 {4, 4, offsetFromFrame0(20, 0), std::nullopt}};
  const render::Image image = draw("keyframes", a);
  EXPECT_GT(count(image, [](const uint8_t* p) { return colourNear(p, 51, 217, 77); }), 10u);    // full green
  EXPECT_GT(count(image, [](const uint8_t* p) { return colourNear(p, 77, 166, 255); }), 10u);   // partial sky blue
  EXPECT_GT(count(image, [](const uint8_t* p) { return colourNear(p, 255, 217, 38); }), 10u);   // gated yellow
  EXPECT_GT(count(image, [](const uint8_t* p) { return colourNear(p, 242, 51, 51); }), 10u);    // rejected red
  EXPECT_GT(count(image, [](const uint8_t* p) { return colourNear(p, 153, 153, 153); }), 10u);  // no prior grey
  a.keyframes.resize(1);
  const render::Image one = draw("keyframes", a);
  EXPECT_EQ(count(one, [](const uint8_t* p) { return colourNear(p, 242, 51, 51); }), 0u);
}

TEST_F(AnalysisLayers, TrajectoryColouredByErrorUsesTheColourMap) {
  render::Analysis a;
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int i = 0; i < 40; ++i) {
    stamps.push_back(int64_t(i) * 100'000'000);
    poses.push_back(offsetFromFrame0(-20.0 + i, 3.0));
    a.odometryError.push_back(i < 39 ? i / 38.0 : std::numeric_limits<double>::quiet_NaN());
  }
  a.odometry = PoseTrajectory(stamps, poses, "odometry");
  const auto blue = [](const uint8_t* p) { return p[2] > 150 && p[0] < 100; };
  const auto red = [](const uint8_t* p) { return p[0] > 100 && p[1] < 90 && p[2] < 60; };  // Turbo's top
  const auto orange = [](const uint8_t* p) { return colourNear(p, 255, 115, 38); };
  const render::Image own = draw("odometry_trajectory", a);
  EXPECT_GT(count(own, orange), 50u);
  EXPECT_EQ(count(own, blue), 0u);
  EXPECT_EQ(count(own, red), 0u);
  const render::Image byError = draw("odometry_trajectory", a, option("colour by", 0, 1));
  EXPECT_LT(count(byError, orange), count(own, orange) / 10);
  EXPECT_GT(count(byError, blue), 20u);  // small errors
  EXPECT_GT(count(byError, red), 20u);   // the largest
  // A fixed range above every error: nothing reaches red.
  const render::Image fixed = draw("odometry_trajectory", a, [](render::Layer& l) {
    option("colour by", 0, 1)(l);
    option("error range (m, 0: largest)", 5.0f, 0)(l);
  });
  EXPECT_EQ(count(fixed, red), 0u);
}

// Coloured by its error, a trajectory names its colour map for the overlay's colour bar: Turbo from
// 0 to the largest error, or to the fixed range; in its own colour, none.
TEST_F(AnalysisLayers, TrajectoryColouredByErrorReportsItsColourScale) {
  render::OffscreenContext context(64, 64);
  render::Analysis a;
  a.odometry = PoseTrajectory({0, 100'000'000}, {offsetFromFrame0(0, 0), offsetFromFrame0(1, 0)}, "odometry");
  a.odometryError = {0.2, 1.5};
  std::unique_ptr<render::Layer> layer = render::makeLayer("odometry_trajectory");
  const render::Scene scene = render::makeScene(*log_, *map_);
  layer->setAnalysis(scene, a);
  EXPECT_FALSE(layer->colourScale());
  option("colour by", 0, 1)(*layer);
  layer->setAnalysis(scene, a);
  ASSERT_TRUE(layer->colourScale());
  EXPECT_EQ(layer->colourScale()->low, 0.0);
  EXPECT_DOUBLE_EQ(layer->colourScale()->high, 1.5);
  EXPECT_EQ(layer->colourScale()->unit, "m");
  option("error range (m, 0: largest)", 5.0f, 0)(*layer);
  layer->setAnalysis(scene, a);
  EXPECT_DOUBLE_EQ(layer->colourScale()->high, 5.0);
}

// A match along a straight road observes no along direction: its ellipse is drawn at the length
// limit (10 m half-axis) along it and at 2 sigma across.
TEST_F(AnalysisLayers, DegenerateMatchEllipseIsClampedAlongTheRoad) {
  render::Analysis a;
  KeyframeInspection k;
  k.keyframePose = offsetFromFrame0(0, 0);
  const Eigen::Vector3d at = planarPose(offsetFromFrame0(0, 0));
  k.start = k.match.estimate = at;
  k.match.path = {at};
  k.match.status = MatchStatus::Degenerate;
  k.match.information = Eigen::Vector3d(0.0, 100.0, 1000.0).asDiagonal();     // nothing along city x
  k.match.covariance = Eigen::Vector3d(0.0, 0.01, 0.001).asDiagonal();      // its pseudo-inverse
  a.inspection = k;
  const render::Image image = draw("match", a);
  int left = image.width, right = -1, top = image.height, bottom = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (colourNear(image.pixel(x, y), 255, 89, 230)) {
        left = std::min(left, x), right = std::max(right, x);
        top = std::min(top, y), bottom = std::max(bottom, y);
      }
  const double pixelsPerMetre = 720.0 / 80.0;
  EXPECT_NEAR((right - left) / pixelsPerMetre, 20.0, 1.0);  // 2 x 10 m
  EXPECT_NEAR((bottom - top) / pixelsPerMetre, 0.4, 0.6);   // 2 x 2 sigma, sigma 0.1 m
}

}  // namespace
}  // namespace hdprior::test
