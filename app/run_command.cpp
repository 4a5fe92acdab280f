#include <cstdio>
#include <filesystem>

#include "app/command_line.h"
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
    std::printf("; optimized ATE rmse %.3f m, max %.3f m, RPE100 %s; matches %zu accepted, %zu degenerate, %zu rejected",
                m.optimized->ate.translation.rmse, m.optimized->ate.translation.max, rpeText(*m.optimized).c_str(),
                m.matches.accepted, m.matches.degenerate, m.matches.rejected);
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

}  // namespace

int runRun(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"out", "config", "odometry-drift", "odometry", "odometry-format", "odometry-frame",
                                         "odometry-times"},
                              .flags = {"no-prior"}, .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior run LOG --out DIR [--no-prior] [--config FILE] "
                                       "[--odometry-drift SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M]] [--odometry FILE "
                                       "[--odometry-format tum|kitti] [--odometry-frame first|city] [--odometry-times FILE]]"});
  const std::filesystem::path out = outputFolder(cl.required("out"));
  const Config config = configOption(cl);
  const OdometryFileOptions odometryFile = odometryFileOptions(cl, "odometry");
  const ArgoverseLog log(cl.positional()[0]);
  PipelineOptions options{.priors = !cl.has("no-prior")};
  if (const auto file = cl.value("odometry")) options.givenOdometry = givenOdometryOf(*file, odometryFile, log);
  ProgressBar bar("run");
  const EvaluatedRun r = runAndWriteLog(log, config, options, out, [&](size_t d, size_t t) { bar(d, t); });
  for (const SkippedSweep& s : r.run.skippedSweeps) {
    std::fprintf(stderr, "hdprior run: warning: skipped %s: %s\n", s.file.string().c_str(), s.problem.c_str());
  }
  printSummary(log, r.run, r.metrics, out);
  return 0;
}

}  // namespace hdprior::app
