#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "engine/error.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "ui/event_navigation.h"
#include "ui/layer_visibility.h"
#include "ui/playback.h"
#include "ui/tuning_bench.h"
#include "ui/view_camera.h"

namespace hdprior {
class ArgoverseLog;
class HdMap;
}  // namespace hdprior

namespace hdprior::ui {

// A log and its map as loaded off the UI thread (no GL).
struct LoadedLog {
  std::unique_ptr<ArgoverseLog> log;
  std::unique_ptr<HdMap> map;
};
// Throws Error naming the file that is wrong.
LoadedLog loadLog(const std::filesystem::path& dir);

// The mouse over the 3-D view: the ground point under it (city frame) and the ground-height
// raster there (NaN outside it).
struct GroundCursor {
  Eigen::Vector3d city = Eigen::Vector3d::Zero();
  double groundHeight = 0.0;
};

// What the panels share: the open log, the renderer with every layer (the default set shown), the current frame,
// playback and camera. Renderer calls need the window's context current.
class AppState {
 public:
  AppState();
  ~AppState();

  // Takes a loaded log: builds the scene and the layers, shows frame 0 (or sets `error`).
  void open(LoadedLog loaded);
  bool hasLog() const { return loaded_.log != nullptr; }
  const ArgoverseLog& log() const { return *loaded_.log; }
  const render::Scene& scene() const { return scene_; }
  const render::Frame& frame() const { return renderer_->frame(); }
  size_t frameCount() const;
  // Clamped to the log; loads the sweep and uploads per-frame data only when it changes. A
  // frame that cannot be loaded (a corrupt sweep file) stops playback and sets `error`; the
  // current frame stays.
  void goToFrame(long long index);
  void step(long long frames) { goToFrame((long long)frame().index + frames); }

  render::Renderer& renderer() { return *renderer_; }
  // The layer named so, or nullptr.
  render::Layer* layer(const std::string& name);
  // The user showing or hiding a layer (the panel's checkbox, a script's `layer` command).
  void setLayerVisible(render::Layer& layer, bool visible) { layerVisibility_.setByUser(layer, visible); }

  // The tuning bench of the open log (its pipeline session, tuned config, selected keyframe).
  TuningBench& bench() { return *bench_; }
  // Once a frame: hands a changed analysis to the renderer's layers.
  void pollBench();
  // Selects keyframe k, matches it with the tuned options and goes to its frame.
  void inspectKeyframe(size_t k);
  // The same for the keyframe nearest the current frame.
  void matchKeyframeAtFrame();
  // The run's event after (direction +1) or before (-1) the current one: selects and matches its
  // keyframe (a skipped sweep: goes to its frame). False when there is none that way.
  bool goToEvent(int direction);
  // A bookmark at the current frame.
  void addBookmark(std::string note);
  // Shows or hides a Diagnostics plot (a name of diagnosticPlots()); the shown keep the bench's order.
  void setPlotShown(const std::string& name, bool shown);
  bool plotShown(const std::string& name) const;
  // The window as drawn, to this PNG after the next draw (the viewer takes it).
  void requestScreenshot(const std::filesystem::path& file) { screenshotRequest = file; }

  Playback playback;
  ViewCamera camera;
  std::optional<GroundCursor> cursor;
  std::optional<Error> error;  // the last frame that failed to load, shown in the status bar
  bool autoMatch = true;       // the tuning panel re-matches on every parameter change
  bool focusOnMatch = true;    // matching a keyframe turns the camera top-down onto it
  std::string selectTab;       // the bench tab to bring to the front on the next frame
  std::optional<std::filesystem::path> screenshotRequest;
  std::vector<std::string> shownPlots;   // the Diagnostics plots shown, in diagnosticPlots() order
  std::vector<Bookmark> bookmarks;
  std::optional<size_t> currentEvent;    // the event last gone to

 private:
  LoadedLog loaded_;
  render::Scene scene_;
  std::unique_ptr<render::Renderer> renderer_;
  LayerVisibility layerVisibility_;
  std::unique_ptr<TuningBench> bench_;
};

}  // namespace hdprior::ui
