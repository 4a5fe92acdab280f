// The view's overlay without a GL context: the scale bar's length choice, the colour bar's
// labels and which blocks the overlay lays out for which layers and cameras.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "render/camera.h"
#include "render/colormap.h"
#include "render/overlays/colour_bar.h"
#include "render/overlays/scale_bar.h"
#include "render/overlays/view_overlay.h"

namespace hdprior::test {
namespace {

TEST(ScaleBar, PicksTheLongestRoundLengthThatFits) {
  EXPECT_DOUBLE_EQ(render::scaleBarLength(80.0 / 720.0, 200.0), 20.0);  // the top view at 720 rows: 22 m fit
  EXPECT_DOUBLE_EQ(render::scaleBarLength(0.1, 200.0), 20.0);           // exactly 20 m fit
  EXPECT_DOUBLE_EQ(render::scaleBarLength(0.25, 200.0), 50.0);
  EXPECT_DOUBLE_EQ(render::scaleBarLength(0.011, 200.0), 2.0);          // zoomed in: 2.2 m fit
  EXPECT_DOUBLE_EQ(render::scaleBarLength(0.0096, 200.0), 1.0);         // 1.92 m fit, 2 m would not
  EXPECT_DOUBLE_EQ(render::scaleBarLength(3.0, 100.0), 200.0);          // zoomed out
  EXPECT_NEAR(render::scaleBarLength(0.004, 100.0), 0.2, 1e-12);        // below a metre
  for (double metresPerPixel : {0.003, 0.05, 0.7, 9.0}) {
    const double pixels = render::scaleBarLength(metresPerPixel, 150.0) / metresPerPixel;
    EXPECT_LE(pixels, 150.0 + 1e-9);
    EXPECT_GT(pixels, 150.0 / 2.5);  // the next round length (at most 2.5 times longer) would not fit
  }
}

TEST(ScaleBar, LabelsInMetres) {
  EXPECT_EQ(render::scaleBarLabel(20.0), "20 m");
  EXPECT_EQ(render::scaleBarLabel(0.5), "0.5 m");
  EXPECT_EQ(render::scaleBarLabel(200.0), "200 m");
}

TEST(ColourBar, LabelsTheEndValuesWithTheirUnit) {
  EXPECT_EQ(render::colourBarLabel(-0.5, "m"), "-0.5 m");
  EXPECT_EQ(render::colourBarLabel(20.345, "m"), "20.3 m");
  EXPECT_EQ(render::colourBarLabel(1234.4, ""), "1234");
  EXPECT_EQ(render::colourBarLabel(-87.25, ""), "-87.2");
}

TEST(Camera, MetresPerPixelOnlyForTopDownViews) {
  const render::Camera top = render::topDownCamera(Eigen::Vector3d::Zero(), 80.0, 16.0 / 9.0);
  ASSERT_TRUE(top.metresPerPixel(720).has_value());
  EXPECT_NEAR(*top.metresPerPixel(720), 80.0 / 720.0, 1e-6);
  EXPECT_FALSE(render::orbitCamera(Eigen::Vector3d::Zero(), 0.0, 0.5, 40.0, 16.0 / 9.0).metresPerPixel(720));
}

// A layer that only reports a colour scale and markers.
class KeyedLayer : public render::Layer {
 public:
  KeyedLayer(std::optional<render::ColourScale> scale, std::vector<render::MarkerKey> keys)
      : scale_(std::move(scale)), keys_(std::move(keys)) {}
  std::string name() const override { return "keyed"; }
  void draw(const render::DrawContext&) const override {}
  std::optional<render::ColourScale> colourScale() const override { return scale_; }
  std::vector<render::MarkerKey> markerKeys() const override { return keys_; }

 private:
  std::optional<render::ColourScale> scale_;
  std::vector<render::MarkerKey> keys_;
};

const render::ColourScale kScore{"NDT score", -10.0, 35.0, "", false, render::turbo};

// The overlay's triangles: the backdrops are the only ones in its translucent dark colour.
size_t backdrops(const render::ScreenCanvas& canvas) {
  size_t n = 0;
  for (const render::ColoredVertex& v : canvas.triangles()) n += v.color.w() > 0.7f && v.color.w() < 0.75f;
  return n / 6;
}

TEST(ViewOverlay, OneBoxPerDistinctScaleTheLegendAndTheScaleBarOfATopView) {
  std::vector<std::unique_ptr<render::Layer>> layers;
  layers.push_back(std::make_unique<KeyedLayer>(kScore, std::vector<render::MarkerKey>{}));
  layers.push_back(std::make_unique<KeyedLayer>(kScore, std::vector<render::MarkerKey>{}));  // the same: one bar
  layers.push_back(std::make_unique<KeyedLayer>(std::nullopt, std::vector<render::MarkerKey>{{"start", {1, 0.5f, 0, 1}}}));
  const render::Camera top = render::topDownCamera(Eigen::Vector3d::Zero(), 80.0, 16.0 / 9.0);
  const render::Camera orbit = render::orbitCamera(Eigen::Vector3d::Zero(), 0.0, 0.5, 40.0, 16.0 / 9.0);
  EXPECT_EQ(backdrops(render::viewOverlay(layers, top, 1280, 720)), 3u);    // colour bar, legend, scale bar
  EXPECT_EQ(backdrops(render::viewOverlay(layers, orbit, 1280, 720)), 2u);  // no scale in perspective
  layers[0]->visible = layers[1]->visible = false;
  EXPECT_EQ(backdrops(render::viewOverlay(layers, orbit, 1280, 720)), 1u);  // hidden layers are not explained
  layers[2]->visible = false;
  EXPECT_TRUE(render::viewOverlay(layers, orbit, 1280, 720).triangles().empty());
}

TEST(ViewOverlay, StaysInsideTheViewClearOfTheInsets) {
  std::vector<std::unique_ptr<render::Layer>> layers;
  layers.push_back(std::make_unique<KeyedLayer>(kScore, std::vector<render::MarkerKey>{{"truth", {0, 1, 0, 1}}}));
  const render::Camera top = render::topDownCamera(Eigen::Vector3d::Zero(), 80.0, 16.0 / 9.0);
  const render::ScreenInsets insets{310, 0, 360, 258};
  const render::ScreenCanvas canvas = render::viewOverlay(layers, top, 1280, 800, insets);
  ASSERT_FALSE(canvas.triangles().empty());
  for (const render::ColoredVertex& v : canvas.triangles()) {
    EXPECT_GE(v.position.x(), insets.left);
    EXPECT_LE(v.position.x(), 1280 - insets.right);
    EXPECT_GE(v.position.y(), insets.top);
    EXPECT_LE(v.position.y(), 800 - insets.bottom);
  }
}

}  // namespace
}  // namespace hdprior::test
