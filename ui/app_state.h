#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "engine/error.h"
#include "engine/geom/ground_measure.h"
#include "engine/pipeline/point_pick.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "ui/event_navigation.h"
#include "ui/layer_visibility.h"
#include "ui/playback.h"
#include "ui/tuning_bench.h"
#include "ui/view_camera.h"
#include "ui/view_session.h"

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
  // Reference per-point ground labels of one frame (view --ground-labels): the ground_labels
  // layer shown, at that frame (one label per point of its sweep).
  void showGroundLabels(std::vector<uint8_t> labels, size_t frameIndex);
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
  // Measures between two city points on the ground (z from the ground raster, or the ego's ground),
  // along and across the ego heading at the current frame; the measure layer draws it.
  GroundMeasure measure(const Eigen::Vector2d& from, const Eigen::Vector2d& to);
  // The inspected keyframe's match: from its estimate to the truth. nullopt without both.
  std::optional<GroundMeasure> measureMatchError();
  // What lies at a city point in the current frame: the sweep point (labelled as the road points
  // label it), the drivable-area polygon and, with ndt_cells shown, the NDT cell of the run's map.
  Pick pick(const Eigen::Vector2d& at);
  // The view as a session: log, frame, camera, layers, tab, plots, bookmarks, A's and B's configurations.
  ViewSession session() const;
  // Restores a session on the open log: layers, plots, bookmarks and tab at once; A's configuration,
  // its run and B's when the session had them (in the background), then the inspected keyframe, the
  // frame and the camera once they are done. Throws Error for a configuration that does not parse.
  void restore(const ViewSession& session);
  // True while a restored session waits for its runs.
  bool restoring() const { return pendingView_.has_value(); }
  // The window as drawn, to this PNG after the next draw (the viewer takes it).
  void requestScreenshot(const std::filesystem::path& file) { screenshotRequest = file; }

  Playback playback;
  ViewCamera camera;
  std::optional<GroundCursor> cursor;
  std::optional<Error> error;  // the last frame that failed to load, shown in the status bar
  bool autoMatch = true;       // the tuning panel re-matches on every parameter change
  bool focusOnMatch = true;    // matching a keyframe turns the camera top-down onto it
  std::string selectTab;       // the bench tab to bring to the front on the next frame
  std::string currentTab;      // the bench tab in front
  std::optional<std::filesystem::path> screenshotRequest;
  std::vector<std::string> shownPlots;   // the Diagnostics plots shown, in diagnosticPlots() order
  std::vector<Bookmark> bookmarks;
  std::optional<size_t> currentEvent;    // the event last gone to
  bool scrollToEvent = false;            // the events list brings it into view on the next frame
  bool measuring = false;                // M: the next two clicks on the ground measure
  bool picking = false;                  // P: the tooltip names what is under the cursor
  std::optional<GroundMeasure> lastMeasure;  // shown in the status bar
  std::string lastPick;                      // the last pick clicked, shown in the status bar
  std::optional<Eigen::Vector3d> measureStart;  // the first click of a measurement

 private:
  LoadedLog loaded_;
  render::Scene scene_;
  std::unique_ptr<render::Renderer> renderer_;
  LayerVisibility layerVisibility_;
  std::unique_ptr<TuningBench> bench_;
  std::optional<std::pair<size_t, std::vector<SubmapLabel>>> pickLabels_;  // the frame's sweep, labelled once
  std::optional<ViewSession> pendingView_;  // a restored session's keyframe, frame and camera, after its runs
  void finishRestore();
};

}  // namespace hdprior::ui
