// AppState's sessions: the view saved to and restored from a ViewSession.
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/config.h"
#include "render/layer.h"
#include "ui/app_state.h"

namespace hdprior::ui {

ViewSession AppState::session() const {
  ViewSession s;
  s.log = log().dir();
  s.frame = frame().index;
  s.camera = sessionCameraOf(camera, scene_.origin);
  for (const auto& l : renderer_->layers()) s.layers.push_back({l->name(), l->visible, l->opacity});
  s.tab = currentTab;
  s.plots = shownPlots;
  s.bookmarks = bookmarks;
  TuningBench& bench = *bench_;
  s.config = formatConfig(bench.config);
  s.ran = bench.summary().has_value();
  s.keyframe = bench.selected();
  if (bench.comparison().active())
    s.comparison = ViewSession::Comparison{bench.comparison().name(), formatConfig(bench.comparison().config()),
                                           bench.comparison().file()};
  return s;
}

void AppState::restore(const ViewSession& s) {
  const Config a = parseConfig(s.config, "session config");
  const std::optional<Config> b = s.comparison ? std::optional(parseConfig(s.comparison->config, "session comparison config"))
                                               : std::nullopt;
  for (const ViewSession::Layer& l : s.layers) {
    if (render::Layer* found = layer(l.name)) {
      setLayerVisible(*found, l.visible);
      found->opacity = l.opacity;
    }
  }
  shownPlots.clear();
  for (const std::string& p : s.plots) setPlotShown(p, true);
  bookmarks = s.bookmarks;
  selectTab = s.tab;
  bench_->config = a;
  bench_->clearComparison();
  if (s.ran) bench_->run();
  if (b) bench_->compare(*b, s.comparison->name, s.comparison->file);
  pendingView_ = s;
  pollBench();
}

// The restored runs have ended: the inspected keyframe, then the frame and the camera as saved.
void AppState::finishRestore() {
  const ViewSession s = std::move(*pendingView_);
  pendingView_.reset();
  if (s.keyframe && *s.keyframe < bench_->keyframeCount()) inspectKeyframe(*s.keyframe);
  goToFrame((long long)s.frame);
  camera = viewCameraOf(s.camera, scene_.origin);
}

}  // namespace hdprior::ui
