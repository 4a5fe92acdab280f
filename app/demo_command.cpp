#include <cstdio>
#include <filesystem>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/common_options.h"
#include "app/progress_bar.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/log_run.h"
#include "engine/sim/demo_log.h"
#include "engine/sim/log_writer.h"

namespace hdprior::app {
namespace {

std::filesystem::path demoLog(const CommandLine& cl, const std::filesystem::path& out) {
  if (!cl.has("town") && !cl.has("seconds")) {
    ProgressBar bar("demo log");
    return demoLogPath([&](size_t d, size_t t) { bar(d, t); });
  }
  SimulationOptions o;
  o.townSeed = uint64_t(cl.integer("town", 1));
  o.seconds = cl.number("seconds", 30.0);
  if (!(o.seconds > 0) || o.seconds > 600) throw Error("option --seconds", "must be in (0, 600]");
  o.outDir = out / "logs";
  ProgressBar bar("sim");
  o.progress = [&](size_t d, size_t t) { bar(d, t); };
  return simulateLog(o).dir;
}

void printRow(const char* name, const ErrorStats& s) {
  std::printf("| %-9s | %6.3f | %6.3f | %6.3f | %6.3f | %6.3f |\n", name, s.mean, s.median, s.rmse, s.std, s.max);
}

}  // namespace

int runDemo(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"out", "town", "seconds"}, .flags = {}, .minPositional = 0, .maxPositional = 0,
                              .usage = "hdprior demo [--out DIR] [--town SEED --seconds N]"});
  const std::filesystem::path out = outputFolder(cl.value("out").value_or("hdprior-demo"));
  const ArgoverseLog log(demoLog(cl, out));
  const Config config;
  RunMetrics metrics;
  for (const bool priors : {false, true}) {
    ProgressBar bar(priors ? "with priors" : "odometry");
    const EvaluatedRun r = runAndWriteLog(log, config, {.priors = priors}, out / (priors ? "priors" : "odometry"),
                                          [&](size_t d, size_t t) { bar(d, t); });
    const PipelineRun& run = r.run;
    metrics = r.metrics;
    if (priors) {
      std::printf("log %s: %zu sweeps, %.0f m; matches %zu accepted, %zu degenerate, %zu rejected; %.1f sweeps/s with priors\n",
                  log.id().c_str(), run.estimate.size(), metrics.odometry.pathLength, metrics.matches.accepted,
                  metrics.matches.degenerate, metrics.matches.rejected, double(run.estimate.size()) / run.times.pipelineS);
    }
  }
  std::printf("\n| ATE (m)   |  mean  | median |  rmse  |  std   |  max   |\n|-----------|--------|--------|--------|--------|--------|\n");
  printRow("odometry", metrics.odometry.ate.translation);
  printRow("optimized", metrics.optimized->ate.translation);
  std::printf("\nlog: %s\nodometry only: %s (odometry.tum, metrics.json, map.ply)\nwith priors:   %s (optimized.tum, "
              "keyframes.json with every match, metrics.json, map.ply)\n",
              log.dir().string().c_str(), (out / "odometry").string().c_str(), (out / "priors").string().c_str());
  return 0;
}

}  // namespace hdprior::app
