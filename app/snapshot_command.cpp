#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/option_checks.h"
#include "engine/changes/map_change_report.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/ground_labels.h"
#include "engine/map/hd_map.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/session.h"
#include "render/analysis.h"
#include "render/layer_registry.h"
#include "render/png_writer.h"
#include "render/snapshot.h"
#include "ui/tuning_bench.h"
#include "ui/view_session.h"

namespace hdprior::app {
namespace {

// What the analysis layers draw: the whole run with priors (over a given odometry file, as `run
// --odometry`) and the batch solve, the file's own trajectory, and a keyframe's inspection and cost landscape.
// The pipeline's analysis of the log; with checkMap, the map check along its final trajectory too.
render::Analysis runAnalysis(const ArgoverseLog& log, const HdMap& map, const Config& config,
                             const std::optional<size_t>& keyframe, const std::optional<GivenOdometry>& given,
                             bool checkMap) {
  Session session(log, &map, config, {.givenOdometry = given});
  session.run();
  session.optimize();
  render::Analysis analysis = render::analysisOf(session);
  if (given) render::setFileTrajectory(analysis, log.cityTEgoAtSweeps(), givenOdometryInCity(*given, log), given->file);
  if (keyframe) render::inspect(analysis, session, map, *keyframe);
  if (checkMap)
    render::setMapChanges(analysis, detectMapChanges(log, map, render::finalTrajectory(analysis), config.roadPoints, ChangeOptions{}),
                          logMapChangeLabels(log.dir()), log.sweepTimestamps());
  return analysis;
}

bool hasLayer(const std::vector<std::string>& layers, const std::string& name) {
  return std::find(layers.begin(), layers.end(), name) != layers.end();
}

bool anyNeedsAnalysis(const std::vector<std::string>& layers) {
  for (const auto& name : layers)
    if (render::needsAnalysis(name)) return true;
  return false;
}

struct SnapshotArguments {
  std::string log, out, size = "1280x720", view = "top", layers, odometry, session, groundLabels;
  std::optional<size_t> frame, keyframe;
  ConfigArguments config;
  OdometryFileArguments odometryFile;
};

// The session's visible layers in drawing order, with their opacities; throws for an unknown layer.
void sessionLayers(const ui::ViewSession& s, const std::string& file, render::SnapshotOptions& options) {
  std::string list;
  for (const auto& l : s.layers) {
    if (!l.visible) continue;
    list += (list.empty() ? "" : ",") + l.name;
    options.opacity[l.name] = l.opacity;
  }
  try {
    options.layers = list.empty() ? std::vector<std::string>{} : render::parseLayerList(list);
  } catch (const Error& e) {
    throw Error(file, e.what());
  }
}

// Run B of the session's comparison: its trajectory and diagnostics, and its match of the keyframe
// nearest A's inspected one, as the app's Compare tab has them.
render::Comparison sessionComparison(const ArgoverseLog& log, const ui::ViewSession::Comparison& b, const std::string& file,
                                     const std::optional<size_t>& frame) {
  const Config config = parseConfig(b.config, file + " (comparison config)");
  const std::unique_ptr<HdMap> map = loadPriorMap(log, config);
  Session session(log, map.get(), config);
  session.run();
  session.optimize();
  render::Comparison comparison = render::comparisonOf(session, b.name);
  if (const auto k = frame ? ui::keyframeNearFrame(session, *frame) : std::nullopt; k && session.hasPriors()) {
    render::Analysis inspected;
    render::inspect(inspected, session, *map, *k);
    comparison.inspection = std::move(inspected.inspection);
    comparison.landscape = std::move(inspected.landscape);
  }
  return comparison;
}

// `snapshot --session FILE`: the saved view's frame, camera, layers and runs, headless.
int runSessionSnapshot(const SnapshotArguments& a) {
  for (const auto& [given, name] : {std::pair{a.frame.has_value(), "--frame"}, {a.keyframe.has_value(), "--keyframe"},
                                    {!a.layers.empty(), "--layers"}, {a.view != "top", "--view"},
                                    {!a.config.file.empty(), "--config"}, {!a.odometry.empty(), "--odometry"},
                                    {!a.groundLabels.empty(), "--ground-labels"}})
    if (given) throw Error("option --session", std::string("cannot be combined with ") + name + " (the session sets it)");
  const ui::ViewSession s = ui::readViewSession(a.session);
  render::SnapshotOptions options;
  render::parseSize(a.size, options.width, options.height);
  sessionLayers(s, a.session, options);
  if (options.layers.empty()) throw Error(a.session, "no layer is visible");
  checkOutputFile(a.out);
  const Config config = parseConfig(s.config, a.session + " (config)");
  const ArgoverseLog log(a.log.empty() ? s.log : std::filesystem::path(a.log));
  if (s.frame >= log.sweepCount())
    throw Error(a.session, "frame " + std::to_string(s.frame) + " is out of range (the log has " + std::to_string(log.sweepCount()) + " sweeps)");
  const std::unique_ptr<HdMap> map = s.ran ? loadPriorMap(log, config)
                                           : std::make_unique<HdMap>(HdMap::load(log.mapFiles(), render::renderMapOptions()));
  render::Analysis analysis =
      s.ran ? runAnalysis(log, *map, config, s.keyframe, std::nullopt, hasLayer(options.layers, "changes")) : render::Analysis{};
  if (s.comparison) {
    std::optional<size_t> frame;
    if (analysis.inspection) frame = analysis.inspection->frame;
    analysis.comparison = sessionComparison(log, *s.comparison, a.session, frame);
  }
  render::Snapshotter snapshotter(log, *map, options);
  snapshotter.setAnalysis(std::move(analysis));
  const render::Camera camera =
      ui::viewCameraOf(s.camera, snapshotter.scene().origin).camera(double(options.width) / options.height);
  render::writePng(a.out, snapshotter.render(s.frame, camera));
  std::printf("wrote %s (%dx%d, frame %zu, session %s)\n", a.out.c_str(), options.width, options.height, s.frame, a.session.c_str());
  return 0;
}

int runSnapshot(const SnapshotArguments& a) {
  if (!a.session.empty()) return runSessionSnapshot(a);
  if (a.log.empty()) throw Error("option LOG", "missing (the log to draw; or --session FILE)");
  // Check every option before the slow part (map loading, the pipeline).
  render::SnapshotOptions options;
  render::parseSize(a.size, options.width, options.height);
  options.view = render::parseView(a.view);
  options.layers = !a.layers.empty() ? render::parseLayerList(a.layers) : render::defaultLayers(options.view);
  if (options.layers.empty()) throw Error("option --layers", "no layer given");
  const std::optional<size_t> keyframe = a.keyframe;
  const bool inspectorView = options.view == render::View::Landscape || options.view == render::View::Inspector;
  if (inspectorView && !keyframe) throw Error("option --view", "the landscape and inspector views need --keyframe K");
  if (!a.frame && !keyframe) throw Error("option --frame", "missing (the frame to draw)");
  const std::filesystem::path out = a.out;
  checkOutputFile(out);
  const Config config = configOf(a.config);
  const OdometryFileOptions odometryFile = odometryFileOptions(a.odometryFile);

  const ArgoverseLog log(a.log);
  if (a.frame && *a.frame >= log.sweepCount())
    throw Error("option --frame", "frame " + std::to_string(*a.frame) + " is out of range (the log has " +
                                      std::to_string(log.sweepCount()) + " sweeps)");
  const std::optional<GivenOdometry> given =
      !a.odometry.empty() ? std::optional(givenOdometryOf(a.odometry, odometryFile, log)) : std::nullopt;
  if (given) givenOdometryInCity(*given, log);  // the file covers the sweeps: checked before the map loads
  options.roadPoints = config.roadPoints;
  if (!a.groundLabels.empty()) {
    if (!a.frame) throw Error("option --ground-labels", "needs --frame (the sweep the labels are of)");
    options.groundLabels = readGroundLabels(a.groundLabels, log.sweep(*a.frame)->points.size());
    options.groundLabelsFrame = *a.frame;
    if (!hasLayer(options.layers, "ground_labels"))
      options.layers = render::parseLayerList(a.layers.empty() ? "drivable,boundary,ego,ground_labels" : a.layers + ",ground_labels");
  }
  const bool analysisNeeded = keyframe || anyNeedsAnalysis(options.layers);
  const bool ndtCells = hasLayer(options.layers, "ndt_cells");
  // The pipeline and the NDT cells need the matcher's map; the others load faster without it.
  const std::unique_ptr<HdMap> map = analysisNeeded || ndtCells ? loadPriorMap(log, config)
                                                                : std::make_unique<HdMap>(HdMap::load(log.mapFiles(), render::renderMapOptions()));
  render::Analysis analysis =
      analysisNeeded ? runAnalysis(log, *map, config, keyframe, given, hasLayer(options.layers, "changes")) : render::Analysis{};
  const size_t frame = a.frame ? *a.frame : analysis.inspection->frame;
  render::Snapshotter snapshotter(log, *map, options);
  snapshotter.setAnalysis(std::move(analysis));
  render::writePng(out, snapshotter.render(frame));
  std::printf("wrote %s (%dx%d, frame %zu)\n", out.string().c_str(), options.width, options.height, frame);
  return 0;
}

// Binds an optional index option: set when given.
CLI::Option* addIndexOption(CLI::App& command, const std::string& name, std::optional<size_t>& index, const std::string& help) {
  return command.add_option_function<long long>(name, [&index](const long long& k) { index = size_t(k); }, help)->check(integerAtLeast(0));
}

}  // namespace

Command addSnapshotCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "snapshot", "one frame drawn headless (OSMesa, no X server) to PNG, with the view's overlay; analysis layers or "
                  "--keyframe run the pipeline (with priors) first");
  auto a = std::make_shared<SnapshotArguments>();
  command->add_option("LOG", a->log, "the log's folder (with --session: default the session's log)");
  command->add_option("--session", a->session,
                      "draw a saved `hdprior view` session (its frame, camera, visible layers, runs A and B); "
                      "--frame, --keyframe, --view, --layers and --config do not apply")
      ->type_name("FILE");
  addIndexOption(*command, "--frame", a->frame, "the sweep to draw (default with --keyframe: the keyframe's)")->type_name("N");
  addIndexOption(*command, "--keyframe", a->keyframe, "inspect keyframe K: re-match it and its cost landscape")->type_name("K");
  command->add_option("--out", a->out, "the PNG to write")->type_name("FILE.png")->required();
  command->add_option("--size", a->size, "the image's size in pixels")->type_name("WxH")->check(imageSize());
  command->add_option("--view", a->view, "the camera; landscape and inspector need --keyframe")
      ->type_name("top|orbit|landscape|inspector")
      ->check(parsedBy([](const std::string& text) { render::parseView(text); }));
  command->add_option("--layers", a->layers,
                      "all (ground, drivable, boundary, lanes, trajectory, sweep, ego) or a list that may also name crossings, "
                      "accumulated, ndt_cells, landscape, odometry_trajectory, optimized_trajectory, file_trajectory, keyframes, road_points, match, ground_labels, "
                      "changes (runs the map check: its verdicts, the lidar's surface and paint) "
                      "(default: all for top and orbit; drivable,landscape,boundary,road_points,match for landscape; "
                      "drivable,boundary,keyframes,road_points,match for inspector)")
      ->type_name("a,b,c")
      ->check(parsedBy([](const std::string& text) { render::parseLayerList(text); }));
  command->add_option("--ground-labels", a->groundLabels,
                      "reference ground labels of the --frame sweep (an Argoverse 2 scene-flow flow_labels.feather, is_ground_0): "
                      "draws the ground_labels layer, the sweep's ground (or road) points coloured by agreement")
      ->type_name("FILE");
  addConfigOption(*command, a->config);
  addGivenOdometryOptions(*command, a->odometry, a->odometryFile,
                          "run the pipeline over this trajectory file "
                          "(TUM or KITTI) instead of the lidar odometry, as run does");
  return {command, [a] { return runSnapshot(*a); }};
}

}  // namespace hdprior::app
