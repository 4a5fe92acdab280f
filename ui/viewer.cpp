#include "ui/viewer.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <numbers>
#include <string>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/ground_labels.h"
#include "engine/map/hd_map.h"
#include "render/png_writer.h"
#include "render/renderer.h"
#include "render/view_cache.h"
#include "render/window_context.h"
#include "ui/camera_input.h"
#include "ui/panels/bench_panel.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/open_log_panel.h"
#include "ui/panels/panel_layout.h"
#include "ui/panels/plots_panel.h"
#include "ui/panels/status_bar.h"
#include "ui/panels/timeline_panel.h"
#include "ui/panels/view_tools.h"

namespace hdprior::ui {
namespace {

size_t speedIndex(const std::string& name) {
  for (size_t i = 0; i < Playback::kSpeedNames.size(); ++i)
    if (name == Playback::kSpeedNames[i]) return i;
  return 0;
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      window_(std::make_unique<render::WindowContext>(options.width, options.height, "hdprior view")),
      state_(std::make_unique<AppState>()),
      viewCache_(std::make_unique<render::ViewCache>()) {
  window_->setSwapInterval(options.swapInterval);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the same layout every start, no file in the working directory
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 3.0f;
  ImGui_ImplGlfw_InitForOpenGL(window_->handle(), true);
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) throw Error("ImGui", "cannot set up its OpenGL 3 renderer");
  imguiReady_ = true;
  lastTime_ = glfwGetTime();
  if (options.log) startLoading(*options.log, true);
}

Viewer::~Viewer() {
  if (loading_.valid()) loading_.wait();
  state_.reset();  // GL objects go while the context is alive
  viewCache_.reset();
  if (imguiReady_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
  }
  if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
}

bool Viewer::running() const { return !stop_ && !window_->shouldClose(); }

void Viewer::startLoading(const std::filesystem::path& dir, bool fromOptions) {
  loadError_.clear();
  loadingFromOptions_ = fromOptions;
  loading_ = std::async(std::launch::async, [dir] { return loadLog(dir); });
}

void Viewer::finishLoading() {
  if (!loading_.valid() || loading_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  try {
    state_->open(loading_.get());
    state_->bench().config = options_.config;
    if (options_.configPath) state_->bench().configPath = *options_.configPath;
    // view --odometry belongs to the log given with it, not to one opened later from the panel.
    if (loadingFromOptions_ && options_.odometry && !state_->bench().openOdometryFile(*options_.odometry))
      throw *state_->bench().odometryFile.failure();
    if (loadingFromOptions_ && options_.groundLabels) state_->showGroundLabels(options_.groundLabels->labels, options_.groundLabels->frame);
    if (loadingFromOptions_ && options_.session) restoreSession(readViewSession(*options_.session), options_.scripted);
  } catch (const Error& e) {
    if (loadingFromOptions_) throw;
    loadError_ = e.what();
  }
}

void Viewer::waitForLog() {
  if (loading_.valid()) loading_.wait();
  finishLoading();
}

// Runs script commands until one needs a drawn frame (wait, screenshot) or the script ends.
void Viewer::runScript() {
  if (!options_.scripted || !state_->hasLog() || state_->restoring()) return;
  if (state_->error) throw *state_->error;  // a script stops at a frame that cannot be loaded
  if (waitFrames_ > 0) {
    --waitFrames_;
    return;
  }
  while (nextCommand_ < options_.script.size()) {
    const ScriptCommand& c = options_.script[nextCommand_++];
    const auto& a = c.args;
    if (c.verb == "frame") state_->goToFrame(std::stoll(a[0]));
    else if (c.verb == "step") state_->step(std::stoll(a[0]));
    else if (c.verb == "play") {
      state_->playback.playing = true;
      state_->playback.speed = int(speedIndex(a[0]));
    } else if (c.verb == "pause") state_->playback.playing = false;
    else if (c.verb == "view") state_->camera.topDown = a[0] == "top";
    else if (c.verb == "layer") {
      render::Layer& layer = *state_->layer(a[0]);
      state_->setLayerVisible(layer, a[1] == "toggle" ? !layer.visible : a[1] == "on");
    } else if (c.verb == "opacity") state_->layer(a[0])->opacity = std::stof(a[1]);
    else if (runBenchCommand(c)) continue;
    else if (c.verb == "wait") {
      waitFrames_ = std::stoi(a[0]);
      return;
    } else if (c.verb == "screenshot") {
      screenshotAfterDraw_ = a[0];
      return;
    } else if (c.verb == "exit") {
      exitAfterDraw_ = true;
      return;
    }
    if (state_->error) throw *state_->error;  // a script stops at a frame that cannot be loaded
  }
  // The end of the script: the final screenshot, then exit.
  if (options_.screenshot) screenshotAfterDraw_ = options_.screenshot;
  exitAfterDraw_ = true;
}

// The tuning bench's script commands; each waits for its work. False for other verbs.
bool Viewer::runBenchCommand(const ScriptCommand& c) {
  TuningBench& bench = state_->bench();
  const auto finish = [&] {
    bench.runner().wait();
    state_->pollBench();
    if (!bench.runner().error().empty()) throw Error("script line " + std::to_string(c.line), bench.runner().error());
  };
  if (c.verb == "run") {
    bench.run();
    finish();
  } else if (c.verb == "step-keyframe") {
    bench.stepKeyframe();
    finish();
  } else if (c.verb == "optimize") {
    bench.optimize();
    finish();
  } else if (c.verb == "check-map") {
    if (!bench.checkMap()) throw Error("script line " + std::to_string(c.line), bench.message + ": 'run' first");
    bench.waitForMapCheck();
    state_->pollBench();
  } else if (c.verb == "keyframe" || c.verb == "match") {
    if (bench.keyframeCount() == 0) throw Error("script line " + std::to_string(c.line), "no keyframes yet: 'run' or 'step-keyframe' first");
    if (c.verb == "keyframe") state_->inspectKeyframe(std::min<size_t>(std::stoull(c.args[0]), bench.keyframeCount() - 1));
    else state_->matchKeyframeAtFrame();
    bench.waitForLandscape();
    state_->pollBench();
    if (!bench.message.empty()) throw Error("script line " + std::to_string(c.line), bench.message);
  } else if (c.verb == "offset") {
    bench.startOffset = {std::stod(c.args[0]), std::stod(c.args[1]), std::stod(c.args[2]) * std::numbers::pi / 180.0};
    bench.matchSelected();
    bench.waitForLandscape();
    state_->pollBench();
  } else if (c.verb == "odometry") {
    OdometryFile& file = bench.odometryFile;
    file.path = c.args[0];
    file.times.clear();
    file.format = c.args.size() > 1 && c.args[1] == "tum" ? OdometryFile::Format::Tum
                  : c.args.size() > 1 && c.args[1] == "kitti" ? OdometryFile::Format::Kitti
                                                               : OdometryFile::Format::Auto;
    file.frame = c.args.size() > 2 && c.args[2] == "city" ? GivenOdometryFrame::City : GivenOdometryFrame::First;
    if (!bench.openOdometryFile()) throw Error("script line " + std::to_string(c.line), file.error());
    state_->pollBench();
  } else if (c.verb == "use-odometry") {
    bench.odometryFile.use = c.args[0] == "file";
  } else if (c.verb == "tab") {
    state_->selectTab = c.args[0];
  } else if (c.verb == "report") {
    std::printf("%s", benchReport(bench).c_str());
    std::string plots;
    for (const std::string& p : state_->shownPlots) plots += " [" + p + "]";
    std::printf("diagnostic plots:%s\nevents: %zu, bookmarks: %zu\n", plots.c_str(), bench.analysis().events.size(),
                state_->bookmarks.size());
  } else if (c.verb == "plot") {
    state_->setPlotShown(c.args[0], c.args[1] == "on");
  } else if (c.verb == "events") {
    const auto& events = bench.analysis().events;
    for (size_t i = 0; i < events.size(); ++i) std::printf("%s\n", eventLine(i, events[i]).c_str());
  } else if (c.verb == "next-event" || c.verb == "prev-event") {
    if (state_->goToEvent(c.verb == "next-event" ? 1 : -1)) bench.waitForLandscape();
    state_->pollBench();
    std::printf("frame %zu\n", state_->frame().index);
  } else if (c.verb == "bookmark") {
    std::string note;
    for (const std::string& word : c.args) note += (note.empty() ? "" : " ") + word;
    state_->addBookmark(note);
    std::printf("bookmark %zu frame %zu %s\n", state_->bookmarks.size() - 1, state_->frame().index, note.c_str());
  } else if (!runDebugCommand(c)) {
    return false;
  }
  return true;
}

// The debugging bench's comparison, measure, pick and session commands. False for other verbs.
bool Viewer::runDebugCommand(const ScriptCommand& c) {
  TuningBench& bench = state_->bench();
  const auto fail = [&](const std::string& why) { throw Error("script line " + std::to_string(c.line), why); };
  const auto number = [&](size_t i) { return std::stod(c.args[i]); };
  if (c.verb == "compare") {
    if (!bench.compareFile(c.args[0])) fail(bench.message);
    bench.comparison().wait();
    state_->pollBench();
    bench.waitForLandscape();
    state_->pollBench();
    if (!bench.comparison().error().empty()) fail("B: " + bench.comparison().error());
  } else if (c.verb == "measure") {
    std::optional<GroundMeasure> m;
    if (c.args[0] == "match") m = state_->measureMatchError();
    else m = state_->measure({number(0), number(1)}, {number(2), number(3)});
    if (!m) fail("'measure match' needs an inspected keyframe with ground truth");
    std::printf("measure: distance %.4f along %.4f lateral %.4f rise %.4f\n", m->distance, m->along, m->lateral, m->rise);
  } else if (c.verb == "pick") {
    std::printf("%s\n", pickText(state_->pick({number(0), number(1)})).c_str());
  } else if (c.verb == "save-session") {
    writeViewSession(c.args[0], state_->session());
    std::printf("wrote %s\n", c.args[0].c_str());
  } else if (c.verb == "load-session") {
    restoreSession(readViewSession(c.args[0]), true);
  } else if (c.verb == "ground-labels") {
    const size_t frame = std::stoull(c.args[1]);
    const ArgoverseLog& log = state_->log();
    if (frame >= log.sweepCount())
      fail("frame " + c.args[1] + " is out of range (the log has " + std::to_string(log.sweepCount()) + " sweeps)");
    state_->showGroundLabels(readGroundLabels(c.args[0], log.sweep(frame)->points.size()), frame);
    std::printf("ground labels of frame %zu\n", frame);
  } else {
    return false;
  }
  return true;
}

// A script waits for the session's runs, keyframe and landscapes before its next command.
void Viewer::restoreSession(const ViewSession& session, bool wait) {
  state_->restore(session);
  if (!wait) return;
  TuningBench& bench = state_->bench();
  while (state_->restoring()) {
    bench.runner().wait();
    bench.comparison().wait();
    state_->pollBench();
  }
  bench.waitForLandscape();
  state_->pollBench();
}

void Viewer::updateCursor() {
  state_->cursor.reset();
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse || !ImGui::IsMousePosValid()) return;
  const int w = window_->framebufferWidth(), h = window_->framebufferHeight();
  const Eigen::Vector2d pixel(io.MousePos.x * io.DisplayFramebufferScale.x, io.MousePos.y * io.DisplayFramebufferScale.y);
  const render::Scene& scene = state_->scene();
  const double fallbackZ = state_->frame().groundZ - scene.origin.z();
  const auto hit = pickGround(state_->camera.camera(double(w) / std::max(1, h)), pixel, w, h, scene, fallbackZ);
  if (!hit) return;
  GroundCursor cursor;
  cursor.city = *hit + scene.origin;
  const double g = scene.map->hasGroundHeight() ? scene.map->groundHeight().bilinearAt(cursor.city.head<2>()) : NAN;
  cursor.groundHeight = g;
  state_->cursor = cursor;
}

void Viewer::drawPanels() {
  if (!state_->hasLog()) {
    if (auto dir = drawOpenLogPanel(loading_.valid(), loadError_)) startLoading(*dir, false);
    return;
  }
  drawLayersPanel(*state_);
  drawBenchPanel(*state_);
  drawPlotsPanel(*state_);
  drawTimelinePanel(*state_);
  drawStatusBar(*state_);
  drawViewTools(*state_);
}

void Viewer::takeScreenshot(const std::filesystem::path& file) {
  render::writePng(file, window_->readBackBuffer());
  std::printf("wrote %s\n", file.string().c_str());
}

void Viewer::frame() {
  glfwPollEvents();
  finishLoading();
  const double now = glfwGetTime(), dt = now - lastTime_;
  lastTime_ = now;
  runScript();

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const int w = window_->framebufferWidth(), h = window_->framebufferHeight();
  if (state_->hasLog()) {
    state_->pollBench();
    handleViewInput(*state_, float(h));
    handleViewTools(*state_);
    state_->goToFrame((long long)state_->playback.advance(state_->frame().index, state_->log().sweepTimestamps(), dt));
    updateCursor();
  }
  drawPanels();
  ImGui::Render();

  if (state_->hasLog()) {
    const render::Camera camera = state_->camera.camera(double(w) / std::max(1, h));
    // While the camera moves, point layers draw a uniform subset; the first still frame draws all.
    const Eigen::Matrix4f viewProjection = camera.viewProjection();
    const bool moving = viewProjection != lastViewProjection_;
    lastViewProjection_ = viewProjection;
    const size_t points = state_->renderer().pointsDrawn();
    const int stride = moving && options_.interactivePoints > 0
                           ? int(std::max<size_t>(1, (points + options_.interactivePoints - 1) / options_.interactivePoints))
                           : 1;
    state_->renderer().setOverlayInsets(viewInsets(ImGui::GetIO().DisplayFramebufferScale.x, state_->shownPlots.size()));
    const uint64_t key = options_.cacheView ? state_->renderer().viewKey(camera) * 31 + uint64_t(stride) : ++uncachedFrames_;
    viewCache_->present(key, w, h, [&] { state_->renderer().draw(camera, w, h, stride); });
  } else {
    render::clearView(w, h);
  }
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

  // Frames count once the log is open (or from the start when there is none: the open-log panel).
  if ((state_->hasLog() || !options_.log) && ++framesWithLog_ == options_.frames) {
    if (options_.screenshot) screenshotAfterDraw_ = options_.screenshot;
    exitAfterDraw_ = exitAfterDraw_ || options_.exitAfterFrames;
  }
  if (screenshotAfterDraw_) {
    takeScreenshot(*screenshotAfterDraw_);
    screenshotAfterDraw_.reset();
  }
  if (state_->screenshotRequest) {
    try {
      std::filesystem::create_directories(state_->screenshotRequest->parent_path());
      takeScreenshot(*state_->screenshotRequest);
      state_->bench().message = "wrote " + state_->screenshotRequest->string();
    } catch (const std::exception& e) {
      state_->bench().message = e.what();
    }
    state_->screenshotRequest.reset();
  }
  if (exitAfterDraw_) stop_ = true;
  window_->swapBuffers();
}

int runViewer(const ViewerOptions& options) {
  Viewer viewer(options);
  while (viewer.running()) viewer.frame();
  return 0;
}

}  // namespace hdprior::ui
