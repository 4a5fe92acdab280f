#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/option_checks.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/ground_labels.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"
#include "engine/sim/demo_log.h"
#include "render/snapshot.h"
#include "ui/view_session.h"
#include "ui/viewer.h"

namespace hdprior::app {
namespace {

namespace fs = std::filesystem;

// The log `hdprior view` opens without a LOG argument: the simulator's demo town, generated into
// the cache on first use. If that fails the app still starts and asks for a directory.
std::optional<fs::path> bundledDemoLog() {
  try {
    if (!fs::is_directory(demoCacheDir() / ("demo-v" + std::to_string(kDemoLogVersion))))
      std::fprintf(stderr, "hdprior view: generating the demo log into %s (first use only)\n", demoCacheDir().c_str());
    return demoLogPath();
  } catch (const Error& e) {
    std::fprintf(stderr, "hdprior view: no demo log (%s); choose a log in the window\n", e.what());
    return std::nullopt;
  }
}

void checkPngPath(const fs::path& out) {
  const fs::path dir = out.parent_path().empty() ? "." : out.parent_path();
  if (!fs::is_directory(dir)) throw Error(out.string(), "its folder does not exist");
  if (fs::is_directory(out)) throw Error(out.string(), "is a directory, expected a .png file name");
}

// The file read and checked against the log (coverage included) before the window opens, as `run` does.
GivenOdometry checkedOdometryFile(const fs::path& file, const OdometryFileOptions& options, const std::optional<fs::path>& dir) {
  if (!dir) throw Error("option --odometry", "needs a log (the demo log could not be generated)");
  const ArgoverseLog log(*dir);
  GivenOdometry given = givenOdometryOf(file, options, log);
  givenOdometryInCity(given, log);
  return given;
}

// The labels of one sweep, checked before the window opens: the frame is the log's, and the file
// holds a label for each of its points.
ui::ViewerOptions::FrameGroundLabels checkedGroundLabels(const std::string& file, size_t frame, const fs::path& logDir) {
  const ArgoverseLog log(logDir);
  if (frame >= log.sweepCount())
    throw Error("option --ground-labels-frame",
                "frame " + std::to_string(frame) + " is out of range (the log has " + std::to_string(log.sweepCount()) + " sweeps)");
  return {readGroundLabels(file, log.sweep(frame)->points.size()), frame};
}

struct ViewArguments {
  std::string log, script, screenshot, size = "1280x800", config, odometry, session, groundLabels;
  long long groundLabelsFrame = 0;
  OdometryFileArguments odometryFile;
  long long frames = 0;  // 0: not given
  bool exit = false;
};

int runView(const ViewArguments& a) {
  ui::ViewerOptions options;
  render::parseSize(a.size, options.width, options.height);
  const bool framesGiven = a.frames > 0 || a.exit;
  if (!a.script.empty() && framesGiven) throw Error("option --script", "cannot be combined with --frames or --exit");
  if (!a.script.empty()) {
    options.script = ui::readViewScript(a.script);
    options.scripted = true;
  }
  if (framesGiven) {
    options.frames = int(std::max(a.frames, 1LL));
    options.exitAfterFrames = a.exit;
  }
  if (!a.screenshot.empty()) {
    checkPngPath(a.screenshot);
    options.screenshot = fs::path(a.screenshot);
    if (!options.scripted && options.frames == 0) throw Error("option --screenshot", "needs --script or --frames");
  }
  if (!a.config.empty()) {
    options.config = loadConfig(a.config);
    options.configPath = fs::path(a.config);
  }
  std::optional<ui::ViewSession> session;
  if (!a.session.empty()) {
    session = ui::readViewSession(a.session);  // checked before the window opens
    options.session = fs::path(a.session);
  }
  if (!a.log.empty() || session) {
    options.log = fs::path(!a.log.empty() ? a.log : session->log.string());
    if (!fs::is_directory(*options.log)) throw Error(options.log->string(), "is not a log directory");
  } else {
    options.log = bundledDemoLog();
  }
  if (!options.log && options.scripted) throw Error("option LOG", "--script needs a log (the demo log could not be generated)");
  const OdometryFileOptions odometryFile = odometryFileOptions(a.odometryFile);
  if (!a.odometry.empty()) options.odometry = checkedOdometryFile(a.odometry, odometryFile, options.log);
  if (!a.groundLabels.empty()) options.groundLabels = checkedGroundLabels(a.groundLabels, size_t(a.groundLabelsFrame), *options.log);
  return ui::runViewer(options);
}

}  // namespace

Command addViewCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand("view", "the desktop app (GLFW, OpenGL 3.3, Dear ImGui) with the tuning bench; "
                                                     "without LOG it opens the demo log");
  auto a = std::make_shared<ViewArguments>();
  command->add_option("LOG", a->log, "the log's folder (default: the session's log, or the simulator's demo log)");
  command->add_option("--session", a->session, "restore a saved session (Save session in the app, or save-session in a script): "
                                               "frame, camera, layers, tab, plots, bookmarks, runs A and B")->type_name("FILE");
  command->add_option("--script", a->script, "run a script, then take the screenshot and quit")->type_name("FILE");
  command->add_option("--frames", a->frames, "take the screenshot after N frames (--exit alone: 1)")->type_name("N")->default_str("")->check(integerAtLeast(1));
  command->add_flag("--exit", a->exit, "quit after --frames N frames");
  command->add_option("--screenshot", a->screenshot, "the window's PNG, with --script or --frames")->type_name("FILE.png");
  command->add_option("--size", a->size, "the window's size in pixels")->type_name("WxH")->check(imageSize());
  command->add_option("--config", a->config, "the configuration the tuning bench starts from (default: the built-in one)")->type_name("FILE");
  command->add_option("--ground-labels", a->groundLabels,
                      "reference ground labels of one sweep (an Argoverse 2 scene-flow flow_labels.feather, is_ground_0): "
                      "the ground_labels layer, shown at that sweep")
      ->type_name("FILE");
  command->add_option("--ground-labels-frame", a->groundLabelsFrame, "the sweep the --ground-labels are of")
      ->type_name("N")
      ->default_val(0)
      ->check(integerAtLeast(0))
      ->needs("--ground-labels");
  addGivenOdometryOptions(*command, a->odometry, a->odometryFile,
                          "open this trajectory file (TUM or KITTI) and run the "
                          "pipeline over it, as run does");
  return {command, [a] { return runView(*a); }};
}

}  // namespace hdprior::app
