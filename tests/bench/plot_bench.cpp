// `hdprior plot` of a 600-keyframe run (target: at most 1 s): the figure of every plot (14 panels)
// drawn from the diagnostics, then with the PNG written (encoding + atomic write), then the whole
// command's work: reading the run folder's keyframes.json, drawing and writing; and the same with a
// second run to compare. The diagnostics are made up (tests/synthetic_diagnostics.h), with every
// status and gaps, as a run's keyframes.json holds them.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include "engine/pipeline/diagnostics_figure.h"
#include "render/png_writer.h"
#include "synthetic_diagnostics.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

constexpr size_t kKeyframes = 600;

// A run folder with a 600-keyframe keyframes.json, under the temporary folder.
fs::path syntheticRun(const std::string& name, double phase) {
  const fs::path dir = fs::temp_directory_path() / ("hdprior_plot_bench_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "keyframes.json") << test::keyframesJson(test::syntheticDiagnostics(kKeyframes, phase));
  return dir;
}

void BM_PlotFigure600Keyframes(benchmark::State& state) {
  const std::vector<DiagnosticsRun> runs{{"run", test::syntheticDiagnostics(kKeyframes)}};
  const auto plots = plotsWithValues(runs);
  for (auto _ : state) benchmark::DoNotOptimize(drawDiagnosticsFigure(runs, plots).rgb.data());
}

void BM_PlotFigureAndPng600Keyframes(benchmark::State& state) {
  const std::vector<DiagnosticsRun> runs{{"run", test::syntheticDiagnostics(kKeyframes)}};
  const auto plots = plotsWithValues(runs);
  const fs::path out = fs::temp_directory_path() / "hdprior_plot_bench.png";
  for (auto _ : state) render::writePng(out, drawDiagnosticsFigure(runs, plots));
  fs::remove(out);
}

// As `hdprior plot RUN_DIR --out F.png [--compare RUN_DIR_B]` does it, less the process start.
void plotCommandWork(benchmark::State& state, bool compare) {
  const fs::path a = syntheticRun("a", 0.0), b = syntheticRun("b", 1.0), out = a / "plot.png";
  for (auto _ : state) {
    std::vector<DiagnosticsRun> runs{{"a", readKeyframeDiagnostics(a / "keyframes.json")}};
    if (compare) runs.push_back({"b", readKeyframeDiagnostics(b / "keyframes.json")});
    render::writePng(out, drawDiagnosticsFigure(runs, plotsWithValues(runs)));
  }
  fs::remove_all(a);
  fs::remove_all(b);
}
void BM_PlotCommand600Keyframes(benchmark::State& state) { plotCommandWork(state, false); }
void BM_PlotCommand600KeyframesCompared(benchmark::State& state) { plotCommandWork(state, true); }

BENCHMARK(BM_PlotFigure600Keyframes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlotFigureAndPng600Keyframes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlotCommand600Keyframes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlotCommand600KeyframesCompared)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hdprior
