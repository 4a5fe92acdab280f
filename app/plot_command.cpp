#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/option_checks.h"
#include "engine/error.h"
#include "engine/pipeline/diagnostic_plots.h"
#include "engine/pipeline/diagnostics_figure.h"
#include "render/png_writer.h"

namespace hdprior::app {
namespace {

namespace fs = std::filesystem;

struct PlotArguments {
  std::string run, out, plots;
  std::optional<std::string> compare;
};

// The run folder's name as the figure shows it ("run_a" for "out/run_a/").
std::string folderName(const fs::path& dir) {
  const fs::path p = fs::weakly_canonical(dir);
  return p.filename().empty() ? p.string() : p.filename().string();
}

// A run folder's diagnostics; `what` names the folder in the messages about it ("argument RUN_DIR").
DiagnosticsRun readRun(const fs::path& dir, const std::string& what) {
  std::error_code ec;
  if (dir.empty()) throw Error(what, "needs a run folder");
  if (!fs::exists(dir, ec)) throw Error(what, dir.string() + ": no such run folder (`hdprior run LOG --out DIR` writes one)");
  if (!fs::is_directory(dir, ec)) throw Error(what, dir.string() + ": not a folder (expected a run folder)");
  const fs::path file = dir / "keyframes.json";
  DiagnosticsRun run{folderName(dir), readKeyframeDiagnostics(file)};
  if (run.rows.empty()) throw Error(file.string(), "no keyframe has a match (was the run made with --no-prior?)");
  return run;
}

int runPlot(const PlotArguments& a) {
  const fs::path out = a.out;
  checkOutputFile(out);
  std::vector<DiagnosticsRun> runs{readRun(a.run, "argument RUN_DIR")};
  if (a.compare) runs.push_back(readRun(*a.compare, "option --compare"));
  const std::vector<const DiagnosticPlot*> plots =
      a.plots.empty() ? plotsWithValues(runs) : parseDiagnosticPlotList(a.plots, "option --plots");
  if (plots.empty()) throw Error((fs::path(a.run) / "keyframes.json").string(), "no keyframe diagnostic has a value to plot");
  const RgbImage figure = drawDiagnosticsFigure(runs, plots);
  render::writePng(out, figure);
  std::printf("wrote %s (%dx%d, %zu plots)\n", out.string().c_str(), figure.width, figure.height, plots.size());
  return 0;
}

}  // namespace

Command addPlotCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "plot", "draw a run folder's keyframe diagnostics (keyframes.json) as time plots over the frame to a PNG, "
              "without a display; with --compare a second run as a second line");
  auto a = std::make_shared<PlotArguments>();
  command->add_option("RUN_DIR", a->run, "a run folder (`hdprior run LOG --out DIR`)")->required();
  command->add_option("--out", a->out, "the PNG to write")->type_name("FILE.png")->required();
  command
      ->add_option("--plots", a->plots,
                   "the plots, top to bottom, among " + diagnosticPlotNames() + " (default: every plot with a value)")
      ->type_name("a,b,c")
      ->check(parsedBy([](const std::string& text) { parseDiagnosticPlotList(text, "option --plots"); }));
  command->add_option("--compare", a->compare, "a second run folder (B), drawn over the first (A) in its own colours")
      ->type_name("RUN_DIR_B");
  return {command, [a] { return runPlot(*a); }};
}

}  // namespace hdprior::app
