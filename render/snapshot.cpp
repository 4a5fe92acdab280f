#include "render/snapshot.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "engine/error.h"
#include "engine/map/hd_map.h"
#include "render/layer_registry.h"
#include "render/layers/road_points_layer.h"
#include "render/offscreen_context.h"
#include "render/renderer.h"

namespace hdprior::render {

View parseView(const std::string& name) {
  if (name == "top") return View::Top;
  if (name == "orbit") return View::Orbit;
  if (name == "landscape") return View::Landscape;
  if (name == "inspector") return View::Inspector;
  throw Error("option --view", "unknown view '" + name + "' (expected top, orbit, landscape or inspector)");
}

std::vector<std::string> defaultLayers(View view) {
  if (view == View::Landscape) return parseLayerList("drivable,boundary,landscape,road_points,match");
  if (view == View::Inspector) return parseLayerList("drivable,boundary,road_points,keyframes,match");
  return standardLayerNames();
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

Camera viewCamera(View view, const Scene& scene, const Frame& frame, double aspect, const Analysis* analysis) {
  const KeyframeInspection* inspection = analysis && analysis->inspection ? &*analysis->inspection : nullptr;
  if (inspection && (view == View::Landscape || view == View::Inspector)) {
    const Eigen::Vector3d estimate = inspection->match.estimate;
    const Eigen::Vector3d at(estimate.x(), estimate.y(), inspection->keyframePose.translation().z());
    if (view == View::Inspector)
      return orbitCamera(at - scene.origin, estimate.z(), 40.0 * std::numbers::pi / 180.0, 60.0, aspect);
    const double extent = analysis->landscape ? 2.0 * analysis->landscape->options.halfExtent : 10.0;
    const Eigen::Vector3d centre = analysis->landscape ? Eigen::Vector3d(analysis->landscape->center.x(), analysis->landscape->center.y(), at.z()) : at;
    return topDownCamera(centre - scene.origin, 1.15 * extent, aspect);
  }
  const Eigen::Vector3d ego = frame.cityTEgo.translation() - scene.origin;
  if (view == View::Top || view == View::Landscape) return topDownCamera(ego, 80.0, aspect);
  const Eigen::Vector3d forward = frame.cityTEgo.linear().col(0);
  const double yaw = std::atan2(forward.y(), forward.x());
  return orbitCamera(ego + Eigen::Vector3d(0, 0, 1.0), yaw, 30.0 * std::numbers::pi / 180.0, 40.0, aspect);
}

struct Snapshotter::State {
  State(const SnapshotOptions& o, const ArgoverseLog& log, const HdMap& map)
      : options(o), context(o.width, o.height), scene(makeScene(log, map)) {
    scene.roadPoints = o.roadPoints;
    scene.groundLabels = o.groundLabels;
    scene.groundLabelsFrame = o.groundLabelsFrame;
  }
  SnapshotOptions options;
  OffscreenContext context;
  Scene scene;
  std::optional<Renderer> renderer;
  std::optional<size_t> frameIndex;
  Frame frame;

  void goTo(size_t index) {
    context.makeCurrent();
    if (frameIndex == index) return;
    frame = makeFrame(scene, index);
    renderer->setFrame(frame);
    frameIndex = index;
  }
};

Snapshotter::Snapshotter(const ArgoverseLog& log, const HdMap& map, const SnapshotOptions& options)
    : state_(std::make_unique<State>(options, log, map)) {
  state_->renderer.emplace();
  state_->renderer->showOverlay = options.overlay;
  for (const auto& name : options.layers.empty() ? defaultLayers(options.view) : options.layers) {
    std::unique_ptr<Layer> layer = makeLayer(name);
    if (auto* points = dynamic_cast<RoadPointsLayer*>(layer.get())) points->showNonGround(options.view == View::Inspector);
    if (const auto it = options.opacity.find(name); it != options.opacity.end()) layer->opacity = it->second;
    state_->renderer->addLayer(std::move(layer));
  }
  state_->renderer->setScene(state_->scene);
}

void Snapshotter::setAnalysis(Analysis analysis) {
  state_->context.makeCurrent();
  state_->renderer->setAnalysis(std::move(analysis));
}

Snapshotter::~Snapshotter() {
  state_->context.makeCurrent();
  state_->renderer.reset();  // GL objects go while their context is alive
}

const Scene& Snapshotter::scene() const { return state_->scene; }

Image Snapshotter::render(size_t index) {
  State& s = *state_;
  s.goTo(index);
  const double aspect = double(s.options.width) / s.options.height;
  return render(index, viewCamera(s.options.view, s.scene, s.frame, aspect, &s.renderer->analysis()));
}

Image Snapshotter::render(size_t index, const Camera& camera) {
  State& s = *state_;
  s.goTo(index);
  s.renderer->draw(camera, s.options.width, s.options.height);
  return s.context.readPixels();
}

}  // namespace hdprior::render
