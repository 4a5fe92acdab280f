#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/option_checks.h"
#include "app/progress_bar.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/log_run.h"
#include "engine/sim/demo_log.h"
#include "engine/sim/log_writer.h"

namespace hdprior::app {
namespace {

struct DemoArguments {
  std::string out = "hdprior-demo";
  long long town = 1;
  double seconds = 30.0;
  bool simulate = false;  // --town or --seconds given: a fresh log instead of the cached one
};

std::filesystem::path demoLog(const DemoArguments& a, const std::filesystem::path& out) {
  if (!a.simulate) {
    ProgressBar bar("demo log");
    return demoLogPath([&](size_t d, size_t t) { bar(d, t); });
  }
  SimulationOptions o;
  o.townSeed = uint64_t(a.town);
  o.seconds = a.seconds;
  if (!(o.seconds > 0) || o.seconds > 600) throw Error("option --seconds", "must be in (0, 600]");
  o.outDir = out / "logs";
  ProgressBar bar("sim");
  o.progress = [&](size_t d, size_t t) { bar(d, t); };
  return simulateLog(o).dir;
}

void printRow(const char* name, const ErrorStats& s) {
  std::printf("| %-9s | %6.3f | %6.3f | %6.3f | %6.3f | %6.3f |\n", name, s.mean, s.median, s.rmse, s.std, s.max);
}

int runDemo(const DemoArguments& a) {
  const std::filesystem::path out = outputFolder(a.out);
  const ArgoverseLog log(demoLog(a, out));
  const Config& config = defaultConfig();
  RunMetrics metrics;
  for (const bool priors : {false, true}) {
    ProgressBar bar(priors ? "with priors" : "odometry");
    const EvaluatedRun r = runAndWriteLog(log, config, {.priors = priors}, out / (priors ? "priors" : "odometry"),
                                          [&](size_t d, size_t t) { bar(d, t); });
    const PipelineRun& run = r.run;
    metrics = r.metrics;
    if (priors) {
      std::printf("log %s: %zu sweeps, %.0f m; priors %s; %.1f sweeps/s with priors\n", log.id().c_str(), run.estimate.size(),
                  metrics.odometry.pathLength, constraintSummary(metrics.matches.constraints).c_str(),
                  double(run.estimate.size()) / run.times.pipelineS);
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

}  // namespace

Command addDemoCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "demo", "simulate a town log (or reuse the cached demo log), run it with and without priors and print the table of ATE");
  auto a = std::make_shared<DemoArguments>();
  command->add_option("--out", a->out, "the output folder")->type_name("DIR");
  CLI::Option* town = command->add_option("--town", a->town, "simulate this town instead of using the cached demo log")
                          ->type_name("SEED")
                          ->check(integerAtLeast(0));
  CLI::Option* seconds = command->add_option("--seconds", a->seconds, "the simulated drive's length, (0, 600] s")
                             ->type_name("N")
                             ->check(finiteNumber());
  command->callback([a, town, seconds] { a->simulate = town->count() + seconds->count() > 0; });
  return {command, [a] { return runDemo(*a); }};
}

}  // namespace hdprior::app
