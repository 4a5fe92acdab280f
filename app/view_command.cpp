#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/common_options.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"
#include "engine/sim/demo_log.h"
#include "render/snapshot.h"
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

}  // namespace

int runView(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"script", "frames", "screenshot", "size", "config", "odometry", "odometry-format",
                                         "odometry-frame", "odometry-times"},
                              .flags = {"exit"},
                              .minPositional = 0, .maxPositional = 1,
                              .usage = "hdprior view [LOG] [--script FILE | --frames N --exit] "
                                       "[--screenshot FILE.png] [--size 1280x800] [--config FILE] [--odometry FILE "
                                       "[--odometry-format tum|kitti] [--odometry-frame first|city] [--odometry-times FILE]]"});
  ui::ViewerOptions options;
  render::parseSize(cl.value("size").value_or("1280x800"), options.width, options.height);
  if (cl.has("script") && (cl.has("frames") || cl.has("exit")))
    throw Error("option --script", "cannot be combined with --frames or --exit");
  if (const auto script = cl.value("script")) {
    options.script = ui::readViewScript(*script);
    options.scripted = true;
  }
  if (cl.has("frames") || cl.has("exit")) {
    options.frames = int(cl.integer("frames", 1));
    if (options.frames < 1) throw Error("option --frames", "must be at least 1");
    options.exitAfterFrames = cl.has("exit");
  }
  if (const auto screenshot = cl.value("screenshot")) {
    checkPngPath(*screenshot);
    options.screenshot = fs::path(*screenshot);
    if (!options.scripted && options.frames == 0) throw Error("option --screenshot", "needs --script or --frames");
  }
  if (const auto config = cl.value("config")) {
    options.config = loadConfig(*config);
    options.configPath = fs::path(*config);
  }
  if (!cl.positional().empty()) {
    options.log = fs::path(cl.positional()[0]);
    if (!fs::is_directory(*options.log)) throw Error(options.log->string(), "is not a log directory");
  } else {
    options.log = bundledDemoLog();
  }
  if (!options.log && options.scripted) throw Error("option LOG", "--script needs a log (the demo log could not be generated)");
  const OdometryFileOptions odometryFile = odometryFileOptions(cl, "odometry");
  if (const auto file = cl.value("odometry")) options.odometry = checkedOdometryFile(*file, odometryFile, options.log);
  return ui::runViewer(options);
}

}  // namespace hdprior::app
