#include "ui/app_state.h"

#include <algorithm>
#include <utility>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/pipeline/point_labels.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/diagnostic_plots.h"
#include "render/layer_registry.h"
#include "render/layers/ground_labels_layer.h"
#include "render/snapshot.h"

namespace hdprior::ui {

LoadedLog loadLog(const std::filesystem::path& dir) {
  LoadedLog loaded;
  // A larger sweep cache than the default: accumulated sweeps hold up to 2 x 25 + 1.
  loaded.log = std::make_unique<ArgoverseLog>(dir, 64);
  loaded.map = std::make_unique<HdMap>(HdMap::load(loaded.log->mapFiles(), render::renderMapOptions()));
  return loaded;
}

AppState::AppState() = default;
AppState::~AppState() = default;

void AppState::open(LoadedLog loaded) {
  renderer_.reset();  // its layers point into the old log and map
  bench_.reset();     // its session too
  loaded_ = std::move(loaded);
  bench_ = std::make_unique<TuningBench>(*loaded_.log, defaultConfig());
  scene_ = render::makeScene(*loaded_.log, *loaded_.map);
  renderer_ = std::make_unique<render::Renderer>();
  for (const std::string& name : render::layerNames()) renderer_->addLayer(render::makeLayer(name));
  renderer_->setScene(scene_);
  layerVisibility_.reset(renderer_->layers());
  playback = Playback{};
  camera = ViewCamera{};
  error.reset();
  if (frameCount() > 0) {
    try {
      renderer_->setFrame(render::makeFrame(scene_, 0));
    } catch (const Error& e) {
      error = e;
    }
    const Eigen::Vector3d forward = frame().cityTEgo.linear().col(0);
    camera.yaw = std::atan2(forward.y(), forward.x());
    camera.follow(frame().cityTEgo.translation() - scene_.origin);
  }
}

void AppState::showGroundLabels(std::vector<uint8_t> labels, size_t frameIndex) {
  scene_.groundLabels = std::move(labels);
  scene_.groundLabelsFrame = frameIndex;
  renderer_->setScene(scene_);
  for (const auto& layer : renderer_->layers())
    if (layer->name() == render::GroundLabelsLayer::kName) setLayerVisible(*layer, true);
  renderer_->setFrame(render::makeFrame(scene_, std::min(frameIndex, frameCount() - 1)));
  camera.follow(frame().cityTEgo.translation() - scene_.origin);
}

size_t AppState::frameCount() const { return hasLog() ? loaded_.log->sweepCount() : 0; }

void AppState::goToFrame(long long index) {
  if (frameCount() == 0) return;
  const size_t clamped = size_t(std::clamp<long long>(index, 0, (long long)frameCount() - 1));
  if (clamped == frame().index && frame().sweep) return;
  try {
    renderer_->setFrame(render::makeFrame(scene_, clamped));
  } catch (const Error& e) {
    error = e;
    playback.playing = false;
    return;
  }
  error.reset();
  camera.follow(frame().cityTEgo.translation() - scene_.origin);
}

void AppState::pollBench() {
  if (!bench_) return;
  if (bench_->poll()) {
    renderer_->setAnalysis(bench_->analysis());
    layerVisibility_.analysisArrived(renderer_->layers(), bench_->analysis());
    if (const auto frame = std::exchange(bench_->frameToShow, std::nullopt)) goToFrame((long long)*frame);
  }
  if (pendingView_ && !bench_->runner().busy() && !bench_->comparison().busy()) finishRestore();
}

void AppState::inspectKeyframe(size_t k) {
  bench_->selectKeyframe(k);
  if (const auto& inspection = bench_->inspection()) {
    goToFrame((long long)inspection->frame);
    if (focusOnMatch) {
      // Top-down on the match, framing the cost landscape with some of the road around it.
      const Eigen::Vector3d& e = inspection->match.estimate;
      camera.topDown = true;
      camera.followEgo = false;
      camera.target = Eigen::Vector3d(e.x(), e.y(), inspection->keyframePose.translation().z()) - scene_.origin;
      camera.topHeight = std::max(30.0, 5.0 * bench_->landscapeOptions.halfExtent);
    }
  }
  pollBench();
}

void AppState::matchKeyframeAtFrame() {
  if (const auto k = bench_->keyframeAtFrame(frame().index)) inspectKeyframe(*k);
}

bool AppState::goToEvent(int direction) {
  const std::vector<RunEvent>& events = bench_->analysis().events;
  const auto next = stepEvent(events, currentEvent, frame().index, direction);
  if (!next) return false;
  currentEvent = *next;
  scrollToEvent = true;
  const RunEvent& e = events[*next];
  if (isFrameEvent(e.kind)) goToFrame((long long)e.frame);
  else inspectKeyframe(e.keyframe);
  return true;
}

void AppState::addBookmark(std::string note) { bookmarks.push_back({frame().index, std::move(note)}); }

void AppState::setPlotShown(const std::string& name, bool shown) {
  std::vector<std::string> next;
  for (const DiagnosticPlot& p : diagnosticPlots())
    if (p.name == name ? shown : plotShown(p.name)) next.push_back(p.name);
  shownPlots = std::move(next);
}

bool AppState::plotShown(const std::string& name) const {
  return std::find(shownPlots.begin(), shownPlots.end(), name) != shownPlots.end();
}

GroundMeasure AppState::measure(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const auto ground = [&](const Eigen::Vector2d& p) { return Eigen::Vector3d(p.x(), p.y(), scene_.groundZ(p, frame().groundZ)); };
  const GroundMeasure m = measureGround(ground(from), ground(to), yawOf(frame().cityTEgo));
  bench_->setMeasure(m);
  pollBench();
  return m;
}

std::optional<GroundMeasure> AppState::measureMatchError() {
  const auto& inspection = bench_->inspection();
  if (!inspection || !inspection->truth) return std::nullopt;
  return measure(inspection->match.estimate.head<2>(), inspection->truth->head<2>());
}

Pick AppState::pick(const Eigen::Vector2d& at) {
  const render::Frame& f = frame();
  if (!f.sweep) return Pick{.at = at};
  if (!pickLabels_ || pickLabels_->first != f.index)
    pickLabels_ = std::pair(f.index, sweepPointLabels(*f.sweep, f.cityTEgo, bench_->config.roadPoints));
  PickOptions options;
  const HdMap* runMap = bench_->runner().map();
  const render::Layer* cells = layer("ndt_cells");
  if (runMap && cells && cells->visible && !bench_->config.match.cellSizes.empty())
    options.ndtCellSize = *std::min_element(bench_->config.match.cellSizes.begin(), bench_->config.match.cellSizes.end());
  return pickAt(at, *f.sweep, pickLabels_->second, f.cityTEgo, options.ndtCellSize ? *runMap : *loaded_.map, options);
}

render::Layer* AppState::layer(const std::string& name) {
  if (!renderer_) return nullptr;
  for (const auto& l : renderer_->layers())
    if (l->name() == name) return l.get();
  return nullptr;
}

}  // namespace hdprior::ui
