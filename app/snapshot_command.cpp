#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/common_options.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/session.h"
#include "render/analysis.h"
#include "render/layer_registry.h"
#include "render/png_writer.h"
#include "render/snapshot.h"

namespace hdprior::app {
namespace {

// What the analysis layers draw: the whole run with priors (over a given odometry file, as `run
// --odometry`) and the batch solve, the file's own trajectory, and a keyframe's inspection and cost landscape.
render::Analysis runAnalysis(const ArgoverseLog& log, const HdMap& map, const Config& config,
                             const std::optional<size_t>& keyframe, const std::optional<GivenOdometry>& given) {
  Session session(log, &map, config, {.givenOdometry = given});
  session.run();
  session.optimize();
  render::Analysis analysis = render::analysisOf(session);
  if (given) render::setFileTrajectory(analysis, log.cityTEgoAtSweeps(), givenOdometryInCity(*given, log), given->file);
  if (keyframe) render::inspect(analysis, session, map, *keyframe);
  return analysis;
}

bool anyNeedsAnalysis(const std::vector<std::string>& layers) {
  for (const auto& name : layers)
    if (render::needsAnalysis(name)) return true;
  return false;
}

}  // namespace

int runSnapshot(const std::vector<std::string>& args) {
  const CommandLine cl(
      args, {.valued = {"frame", "out", "size", "view", "layers", "keyframe", "config", "odometry", "odometry-format",
                        "odometry-frame", "odometry-times"},
             .flags = {},
             .minPositional = 1, .maxPositional = 1,
             .usage = "hdprior snapshot LOG (--frame N | --keyframe K) --out FILE.png [--size 1280x720] "
                      "[--view top|orbit|landscape|inspector] [--layers a,b,c] [--config FILE] [--odometry FILE [--odometry-format "
                      "tum|kitti] [--odometry-frame first|city] [--odometry-times FILE]]; "
                      "  defaults: --view top, --layers all (top, orbit) | drivable,landscape,boundary,road_points,match "
                      "(landscape) | drivable,boundary,keyframes,road_points,match (inspector, non-ground shown); "
                      "landscape and inspector need --keyframe; --frame defaults to keyframe K's frame"});
  // Check every option before the slow part (map loading, the pipeline).
  render::SnapshotOptions options;
  render::parseSize(cl.value("size").value_or("1280x720"), options.width, options.height);
  options.view = render::parseView(cl.value("view").value_or("top"));
  options.layers = cl.value("layers") ? render::parseLayerList(*cl.value("layers")) : render::defaultLayers(options.view);
  if (options.layers.empty()) throw Error("option --layers", "no layer given");
  std::optional<size_t> keyframe;
  if (cl.has("keyframe")) {
    const long long k = cl.integer("keyframe", -1);
    if (k < 0) throw Error("option --keyframe", "must not be negative");
    keyframe = size_t(k);
  }
  const bool inspectorView = options.view == render::View::Landscape || options.view == render::View::Inspector;
  if (inspectorView && !keyframe) throw Error("option --view", "the landscape and inspector views need --keyframe K");
  if (!cl.has("frame") && !keyframe) throw Error("option --frame", "missing (the frame to draw)");
  const long long frameOption = cl.integer("frame", 0);
  if (frameOption < 0) throw Error("option --frame", "must not be negative");
  const std::filesystem::path out = cl.required("out");
  const std::filesystem::path outDir = out.parent_path().empty() ? "." : out.parent_path();
  if (!std::filesystem::is_directory(outDir)) throw Error(out.string(), "its folder does not exist");
  if (std::filesystem::is_directory(out)) throw Error(out.string(), "is a directory, expected a .png file name");
  const Config config = cl.value("config") ? loadConfig(*cl.value("config")) : Config{};
  const OdometryFileOptions odometryFile = odometryFileOptions(cl, "odometry");

  const ArgoverseLog log(cl.positional()[0]);
  if (cl.has("frame") && size_t(frameOption) >= log.sweepCount())
    throw Error("option --frame", "frame " + std::to_string(frameOption) + " is out of range (the log has " +
                                      std::to_string(log.sweepCount()) + " sweeps)");
  const std::optional<GivenOdometry> given =
      cl.value("odometry") ? std::optional(givenOdometryOf(*cl.value("odometry"), odometryFile, log)) : std::nullopt;
  if (given) givenOdometryInCity(*given, log);  // the file covers the sweeps: checked before the map loads
  const bool analysisNeeded = keyframe || anyNeedsAnalysis(options.layers);
  const bool ndtCells = std::find(options.layers.begin(), options.layers.end(), "ndt_cells") != options.layers.end();
  // The pipeline and the NDT cells need the matcher's map; the others load faster without it.
  const std::unique_ptr<HdMap> map = analysisNeeded || ndtCells ? loadPriorMap(log, config)
                                                                : std::make_unique<HdMap>(HdMap::load(log.mapFiles(), render::renderMapOptions()));
  render::Analysis analysis = analysisNeeded ? runAnalysis(log, *map, config, keyframe, given) : render::Analysis{};
  const size_t frame = cl.has("frame") ? size_t(frameOption) : analysis.inspection->frame;
  render::Snapshotter snapshotter(log, *map, options);
  snapshotter.setAnalysis(std::move(analysis));
  render::writePng(out, snapshotter.render(frame));
  std::printf("wrote %s (%dx%d, frame %zu)\n", out.string().c_str(), options.width, options.height, frame);
  return 0;
}

}  // namespace hdprior::app
