#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/progress_bar.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/log_run.h"

namespace hdprior::app {
namespace {

std::string rpeText(const TrajectoryEvaluation& e) {
  if (!e.rpe100.segments) return "n/a (path < 100 m)";
  char b[64];
  std::snprintf(b, sizeof b, "%.3f %%", e.rpe100.translationPercent);
  return b;
}

void printSummary(const ArgoverseLog& log, const PipelineRun& run, const RunMetrics& m, const std::filesystem::path& out) {
  const double s = run.times.pipelineS;
  std::printf("run %s: %zu sweeps", log.id().c_str(), run.estimate.size());
  if (!run.skippedSweeps.empty()) std::printf(" (%zu unreadable skipped)", run.skippedSweeps.size());
  std::printf(", %zu keyframes, %.1f s (%.1f sweeps/s); ", run.odometry->keyframes().size(), s,
              s > 0 ? double(run.estimate.size()) / s : 0.0);
  std::printf("odometry ATE rmse %.3f m, max %.3f m, RPE100 %s", m.odometry.ate.translation.rmse,
              m.odometry.ate.translation.max, rpeText(m.odometry).c_str());
  if (m.optimized) {
    std::printf("; optimized ATE rmse %.3f m, max %.3f m, RPE100 %s; priors %s", m.optimized->ate.translation.rmse,
                m.optimized->ate.translation.max, rpeText(*m.optimized).c_str(), constraintSummary(m.matches.constraints).c_str());
  }
  if (run.odometryDrift.active()) {
    std::printf("; injected odometry drift: scale %g, yaw %g deg/100 m, pitch %g deg/100 m", run.odometryDrift.scale,
                run.odometryDrift.yawDegPer100m, run.odometryDrift.pitchDegPer100m);
  }
  if (run.givenOdometry) {
    std::printf("; odometry from %s (%s, frame %s)", run.givenOdometry->file.c_str(), trajectoryFormatName(run.givenOdometry->format),
                givenOdometryFrameName(run.givenOdometry->frame));
  }
  std::printf("; wrote %s\n", out.string().c_str());
}

struct RunArguments {
  std::string log, out, odometry;
  bool noPrior = false;
  ConfigArguments config;
  OdometryFileArguments odometryFile;
};

int runRun(const RunArguments& a) {
  const std::filesystem::path out = outputFolder(a.out);
  const Config config = configOf(a.config);
  const OdometryFileOptions odometryFile = odometryFileOptions(a.odometryFile);
  const ArgoverseLog log(a.log);
  PipelineOptions options{.priors = !a.noPrior};
  if (!a.odometry.empty()) options.givenOdometry = givenOdometryOf(a.odometry, odometryFile, log);
  ProgressBar bar("run");
  const EvaluatedRun r = runAndWriteLog(log, config, options, out, [&](size_t d, size_t t) { bar(d, t); });
  for (const SkippedSweep& s : r.run.skippedSweeps) {
    std::fprintf(stderr, "hdprior run: warning: skipped %s: %s\n", s.file.string().c_str(), s.problem.c_str());
  }
  printSummary(log, r.run, r.metrics, out);
  return 0;
}

}  // namespace

Command addRunCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "run", "the pipeline over a whole log: lidar odometry, HD-map priors, pose graph, every sweep corrected; "
             "trajectories, keyframes, metrics and map into DIR");
  auto a = std::make_shared<RunArguments>();
  addLogArgument(*command, a->log);
  command->add_option("--out", a->out, "the output folder")->type_name("DIR")->required();
  command->add_flag("--no-prior", a->noPrior, "odometry only: no HD-map priors, no pose graph");
  addConfigOption(*command, a->config);
  addOdometryDriftOption(*command, a->config);
  addGivenOdometryOptions(*command, a->odometry, a->odometryFile,
                          "the vehicle's poses from another system's trajectory "
                          "(TUM or KITTI) instead of the lidar odometry");
  return {command, [a] { return runRun(*a); }};
}

}  // namespace hdprior::app
