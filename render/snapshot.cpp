#include "render/snapshot.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "engine/error.h"
#include "engine/map/hd_map.h"
#include "render/layer_registry.h"
#include "render/offscreen_context.h"
#include "render/renderer.h"

namespace hdprior::render {

View parseView(const std::string& name) {
  if (name == "top") return View::Top;
  if (name == "orbit") return View::Orbit;
  throw Error("option --view", "unknown view '" + name + "' (expected top or orbit)");
}

void parseSize(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw Error("option --size", "expected WIDTHxHEIGHT with each in 16..8192, got '" + text + "'");
  width = w;
  height = h;
}

HdMapOptions renderMapOptions() {
  HdMapOptions options;
  options.ndtCellSizes.clear();
  options.boundaryDistance = false;
  return options;
}

Camera viewCamera(View view, const Scene& scene, const Frame& frame, double aspect) {
  const Eigen::Vector3d ego = frame.cityTEgo.translation() - scene.origin;
  if (view == View::Top) return topDownCamera(ego, 80.0, aspect);
  const Eigen::Vector3d forward = frame.cityTEgo.linear().col(0);
  const double yaw = std::atan2(forward.y(), forward.x());
  return orbitCamera(ego + Eigen::Vector3d(0, 0, 1.0), yaw, 30.0 * std::numbers::pi / 180.0, 40.0, aspect);
}

struct Snapshotter::State {
  State(const SnapshotOptions& o, const ArgoverseLog& log, const HdMap& map)
      : options(o), context(o.width, o.height), scene(makeScene(log, map)) {}
  SnapshotOptions options;
  OffscreenContext context;
  Scene scene;
  std::optional<Renderer> renderer;
  std::optional<size_t> frameIndex;
  Frame frame;
};

Snapshotter::Snapshotter(const ArgoverseLog& log, const HdMap& map, const SnapshotOptions& options)
    : state_(std::make_unique<State>(options, log, map)) {
  state_->renderer.emplace();
  for (const auto& name : options.layers.empty() ? standardLayerNames() : options.layers)
    state_->renderer->addLayer(makeLayer(name));
  state_->renderer->setScene(state_->scene);
}

Snapshotter::~Snapshotter() {
  state_->context.makeCurrent();
  state_->renderer.reset();  // GL objects go while their context is alive
}

Image Snapshotter::render(size_t index) {
  State& s = *state_;
  s.context.makeCurrent();
  if (s.frameIndex != index) {
    s.frame = makeFrame(s.scene, index);
    s.renderer->setFrame(s.frame);
    s.frameIndex = index;
  }
  const double aspect = double(s.options.width) / s.options.height;
  s.renderer->draw(viewCamera(s.options.view, s.scene, s.frame, aspect), s.options.width, s.options.height);
  return s.context.readPixels();
}

}  // namespace hdprior::render
