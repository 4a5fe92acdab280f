#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "render/camera.h"
#include "render/gl_loader.h"
#include "render/layer_registry.h"
#include "render/offscreen_context.h"
#include "render/renderer.h"
#include "render/snapshot.h"
#include "test_data.h"

namespace hdprior::test {
namespace {

render::GlProc missingEverything(const char*) { return nullptr; }

TEST(GlLoader, NamesTheFirstMissingFunction) {
  try {
    render::loadGlFunctions(missingEverything, "test context");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("test context"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("glActiveTexture"), std::string::npos) << e.what();
  }
  render::OffscreenContext reload(16, 16);  // the table is the offscreen context's again
}

// The app's view cache key: changes with the camera, the frame, every layer setting and the
// overlay's, and only then.
TEST(RendererViewKey, ChangesExactlyWhenTheViewWould) {
  const ArgoverseLog log(sharedLog());
  const HdMap map = HdMap::load(log.mapFiles(), render::renderMapOptions());
  render::OffscreenContext context(64, 64);
  render::Renderer renderer;
  for (const auto& name : render::layerNames()) renderer.addLayer(render::makeLayer(name));
  const render::Scene scene = render::makeScene(log, map);
  renderer.setScene(scene);
  renderer.setFrame(render::makeFrame(scene, 0));
  const render::Camera camera = render::topDownCamera(Eigen::Vector3d::Zero(), 80.0, 1.0);

  const uint64_t key = renderer.viewKey(camera);
  EXPECT_EQ(renderer.viewKey(camera), key);
  EXPECT_NE(renderer.viewKey(render::topDownCamera(Eigen::Vector3d(0.1, 0, 0), 80.0, 1.0)), key);

  const auto& layers = renderer.layers();
  const auto found = std::find_if(layers.begin(), layers.end(), [](const auto& l) { return l->name() == "sweep"; });
  ASSERT_NE(found, layers.end());
  render::Layer& sweep = **found;
  sweep.visible = false;
  EXPECT_NE(renderer.viewKey(camera), key);
  sweep.visible = true;
  EXPECT_EQ(renderer.viewKey(camera), key);
  sweep.opacity = 0.5f;
  EXPECT_NE(renderer.viewKey(camera), key);
  sweep.opacity = 1.0f;
  renderer.showOverlay = false;
  EXPECT_NE(renderer.viewKey(camera), key);
  renderer.showOverlay = true;
  renderer.setOverlayInsets({310, 0, 360, 258});  // the app's panels
  EXPECT_NE(renderer.viewKey(camera), key);
  renderer.setOverlayInsets({});
  EXPECT_EQ(renderer.viewKey(camera), key);
  *sweep.options().front().integer = 1;  // colour by intensity
  EXPECT_NE(renderer.viewKey(camera), key);
  *sweep.options().front().integer = 0;
  renderer.rebuild(sweep);  // new data, even if it is the same
  const uint64_t rebuilt = renderer.viewKey(camera);
  EXPECT_NE(rebuilt, key);
  renderer.setFrame(render::makeFrame(scene, 1));
  const uint64_t nextFrame = renderer.viewKey(camera);
  EXPECT_NE(nextFrame, rebuilt);
  renderer.setAnalysis({});  // new pipeline results
  EXPECT_NE(renderer.viewKey(camera), nextFrame);
  EXPECT_EQ(renderer.pointsDrawn(), log.sweep(0)->points.size() + log.sweep(1)->points.size());
}

// Thinned drawing (every n-th point while the camera moves) draws fewer points, the full draw is
// unchanged.
TEST(RendererPointStride, ThinsOnlyTheLidarLayers) {
  const ArgoverseLog log(sharedLog());
  const HdMap map = HdMap::load(log.mapFiles(), render::renderMapOptions());
  render::OffscreenContext context(320, 180);
  render::Renderer renderer;
  renderer.addLayer(render::makeLayer("sweep"));
  const render::Scene scene = render::makeScene(log, map);
  renderer.setScene(scene);
  const render::Frame frame = render::makeFrame(scene, 0);
  renderer.setFrame(frame);
  const render::Camera camera = render::viewCamera(render::View::Top, scene, frame, 320.0 / 180.0);
  const auto litPixels = [&](int stride) {
    renderer.draw(camera, 320, 180, stride);
    const render::Image image = context.readPixels();
    size_t lit = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) lit += image.pixel(x, y)[0] + image.pixel(x, y)[1] + image.pixel(x, y)[2] > 200;
    return lit;
  };
  const size_t full = litPixels(1), thinned = litPixels(8);
  EXPECT_GT(full, 1000u);
  EXPECT_LT(thinned, full * 3 / 4);
  EXPECT_GT(thinned, full / 20);
  EXPECT_EQ(litPixels(1), full);
}

}  // namespace
}  // namespace hdprior::test
