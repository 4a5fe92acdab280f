#pragma once
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"
#include "ui/app_state.h"
#include "ui/view_script.h"

namespace hdprior::render {
class ViewCache;
class WindowContext;
}

namespace hdprior::ui {

struct ViewerOptions {
  std::optional<std::filesystem::path> log;  // none: ask for a directory
  std::vector<ScriptCommand> script;         // run once the log is open; the app exits at its end
  bool scripted = false;
  int frames = 0;  // > 0: after this many frames with the log open (or without a log), screenshot and/or exit
  bool exitAfterFrames = false;
  std::optional<std::filesystem::path> screenshot;  // taken at the end of the script or the frames
  Config config = defaultConfig();                  // the tuning bench starts from it ...
  std::optional<std::filesystem::path> configPath;  // ... read from this file (its save/load path)
  std::optional<GivenOdometry> odometry;            // view --odometry FILE: opened in the Pipeline tab
  std::optional<std::filesystem::path> session;     // view --session FILE: restored once the log is open
  struct FrameGroundLabels {
    std::vector<uint8_t> labels;  // one per point of the frame's sweep (is_ground_0)
    size_t frame = 0;
  };
  std::optional<FrameGroundLabels> groundLabels;  // view --ground-labels FILE: shown once the log is open
  int width = 1280, height = 800;
  int swapInterval = 1;  // 0: do not wait for vertical blank
  bool cacheView = true;  // false: draw every layer every frame (benchmarks of the full draw)
  // While the camera moves, lidar layers draw about this many points (0: all, always).
  size_t interactivePoints = 100000;
};

// The `hdprior view` window: the 3-D view of the AppState's renderer under ImGui panels.
// A load error of the log given in the options is thrown (Error) out of frame(); one from the
// open-log panel is shown in the panel.
class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options);  // throws Error("GLFW", ...) without a display
  ~Viewer();
  bool running() const;
  // One frame: events, input, playback, panels, 3-D view, script step, screenshot, swap.
  void frame();
  // Blocks until the log being loaded is open (benchmarks, tests).
  void waitForLog();
  AppState& state() { return *state_; }

 private:
  void startLoading(const std::filesystem::path& dir, bool fromOptions);
  void finishLoading();
  void runScript();
  bool runBenchCommand(const ScriptCommand& command);
  bool runDebugCommand(const ScriptCommand& command);
  void restoreSession(const ViewSession& session, bool wait);
  void updateCursor();
  void drawPanels();
  void takeScreenshot(const std::filesystem::path& file);

  ViewerOptions options_;
  std::unique_ptr<render::WindowContext> window_;
  bool imguiReady_ = false;
  std::unique_ptr<AppState> state_;
  std::unique_ptr<render::ViewCache> viewCache_;
  uint64_t uncachedFrames_ = 0;
  Eigen::Matrix4f lastViewProjection_ = Eigen::Matrix4f::Zero();
  std::future<LoadedLog> loading_;
  bool loadingFromOptions_ = false;
  std::string loadError_;
  size_t nextCommand_ = 0;
  int waitFrames_ = 0;
  int framesWithLog_ = 0;
  std::optional<std::filesystem::path> screenshotAfterDraw_;
  bool exitAfterDraw_ = false;
  bool stop_ = false;
  double lastTime_ = 0.0;
};

// Runs the window until it is closed or the script / frame count ends; returns the exit status.
int runViewer(const ViewerOptions& options);

}  // namespace hdprior::ui
