#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/progress_bar.h"
#include "engine/changes/change_report_files.h"
#include "engine/changes/map_change_report.h"
#include "engine/error.h"
#include "engine/eval/change_scoring.h"
#include "engine/io/file_bytes.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/tum_trajectory.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/log_run.h"

namespace hdprior::app {
namespace {

struct ChangesArguments {
  std::string log, out, run;
  ConfigArguments config;
};

// The run's globally consistent poses: RUN/optimized.tum, or RUN/odometry.tum of a run without priors.
PoseTrajectory runPoses(const std::filesystem::path& run) {
  if (!std::filesystem::is_directory(run)) throw Error(run.string(), "is not a run folder (hdprior run --out)");
  for (const char* name : {"optimized.tum", "odometry.tum"})
    if (std::filesystem::exists(run / name)) return readTum(run / name);
  throw Error(run.string(), "has neither optimized.tum nor odometry.tum (hdprior run --out)");
}

int runChanges(const ChangesArguments& a) {
  const std::filesystem::path out = outputFolder(a.out);
  const Config config = configOf(a.config);
  const ArgoverseLog log(a.log);
  PoseTrajectory poses;
  if (!a.run.empty()) {
    poses = runPoses(a.run);
  } else {
    ProgressBar bar("run");
    poses = runAndWriteLog(log, config, {}, out / "run", [&](size_t d, size_t t) { bar(d, t); }).run.final();
  }
  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<HdMap> map = loadCheckedMap(log, poses, config.roadPoints, ChangeOptions{});
  ProgressBar bar("changes");
  const MapChangeReport report =
      detectMapChanges(log, *map, poses, config.roadPoints, ChangeOptions{}, [&](size_t d, size_t t) { bar(d, t); });
  writeChangeReport(out, report, log.id());
  std::string scored;
  if (const std::optional<std::vector<MapChangeLabel>> labels = logMapChangeLabels(log.dir())) {
    const MapCheckScore score = scoreMapCheck(report, *labels);
    writeFileAtomically(out / "score.json", changeScoreJson(score));
    scored = "; against map_change.json: " + changeScoreLine(score);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  size_t contradicted = 0, consistent = 0;
  for (const DrivableAreaVerdict& v : report.drivableAreas) {
    contradicted += v.verdict == MapVerdict::Contradicted;
    consistent += v.verdict == MapVerdict::Consistent;
  }
  size_t crossingsContradicted = 0, crossingsConsistent = 0;
  for (const CrossingVerdict& c : report.crossings) {
    crossingsContradicted += c.verdict == MapVerdict::Contradicted;
    crossingsConsistent += c.verdict == MapVerdict::Consistent;
  }
  size_t linesContradicted = 0, linesConsistent = 0;
  for (const LaneLineStretch& s : report.laneLines) {
    linesContradicted += s.verdict == MapVerdict::Contradicted;
    linesConsistent += s.verdict == MapVerdict::Consistent;
  }
  std::printf("changes %s: %zu sweeps over %.2f km, %.2f km of boundary observed; drivable areas: %zu contradicted, "
              "%zu consistent, %zu unobserved; %zu missing surfaces; crossings: %zu contradicted, %zu consistent, "
              "%zu missing; lane-line stretches: %zu contradicted, %zu consistent%s; %.1f s; wrote %s\n",
              log.id().c_str(), report.frames, report.drivenKm, report.observedBoundaryKm, contradicted, consistent,
              report.drivableAreas.size() - contradicted - consistent, report.missing.size(), crossingsContradicted,
              crossingsConsistent, report.missingCrossings.size(), linesContradicted, linesConsistent, scored.c_str(), seconds,
              out.string().c_str());
  return 0;
}

}  // namespace

Command addChangesCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "changes", "where the lidar contradicts the HD map: a verdict per drivable-area boundary stretch and the road "
                 "surface the map lacks, along a run's globally consistent poses; changes.geojson and summary.json into DIR "
                 "(and score.json against a simulated log's map_change.json)");
  auto a = std::make_shared<ChangesArguments>();
  addLogArgument(*command, a->log);
  command->add_option("--out", a->out, "the output folder")->type_name("DIR")->required();
  command->add_option("--run", a->run, "a run folder of this log (hdprior run --out) whose poses to use; "
                                       "without it the log is run first, into DIR/run")
      ->type_name("RUN_DIR");
  addConfigOption(*command, a->config);
  return {command, [a] { return runChanges(*a); }};
}

}  // namespace hdprior::app
