#include <cstdio>
#include <filesystem>

#include "app/command_line.h"
#include "app/commands.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/odometry_run.h"

namespace hdprior::app {
namespace {

// A progress bar on stderr, redrawn only when it changes.
class ProgressBar {
 public:
  void operator()(size_t done, size_t total) {
    const int width = 40, filled = int(width * done / std::max<size_t>(total, 1));
    if (filled == last_ && done != total) return;
    last_ = filled;
    std::fprintf(stderr, "\r[%s%s] %zu/%zu sweeps", std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
                 done, total);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

 private:
  int last_ = -1;
};

}  // namespace

int runRun(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"out", "config"}, .flags = {"no-prior"}, .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior run LOG --out DIR --no-prior [--config FILE]"});
  const std::filesystem::path out = cl.required("out");
  const Config config = cl.value("config") ? loadConfig(*cl.value("config")) : Config{};
  if (!cl.has("no-prior")) {
    throw Error("option --no-prior", "HD-map priors are not available yet; run the odometry alone with --no-prior");
  }
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out)) throw Error(out.string(), "exists and is not a folder");
  const ArgoverseLog log(cl.positional()[0]);
  ProgressBar bar;
  const OdometryRun run = runOdometry(log, config, [&](size_t d, size_t t) { bar(d, t); });
  const RunMetrics metrics = evaluateRun(run);
  writeRunOutputs(out, log, run, metrics);
  const TrajectoryEvaluation& e = metrics.anchored;
  std::printf("run %s: %zu sweeps, %zu keyframes, %.1f s (%.1f sweeps/s); ATE rmse %.3f m, max %.3f m; RPE100 %s; wrote %s\n",
              log.id().c_str(), run.estimate.size(), run.odometry->keyframes().size(), run.wallSeconds,
              run.wallSeconds > 0 ? double(run.estimate.size()) / run.wallSeconds : 0.0, e.ate.translation.rmse,
              e.ate.translation.max,
              e.rpe100.segments ? (std::to_string(e.rpe100.translationPercent) + " %").c_str() : "n/a (path < 100 m)",
              out.string().c_str());
  return 0;
}

}  // namespace hdprior::app
