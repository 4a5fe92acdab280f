#pragma once
#include <functional>

namespace CLI {
class App;
}

namespace hdprior::app {

// One subcommand of `hdprior`: its CLI11 parser (options, defaults, help) and what runs it once the
// command line has been parsed and checked. `run` returns the exit status; bad input throws
// hdprior::Error, which main turns into one line and exit status 2.
struct Command {
  CLI::App* parser = nullptr;
  std::function<int()> run;
};

// Each adds its subcommand to the `hdprior` parser.
Command addInfoCommand(CLI::App& hdprior);
Command addExportMapCommand(CLI::App& hdprior);
Command addSnapshotCommand(CLI::App& hdprior);
Command addRunCommand(CLI::App& hdprior);
Command addSimCommand(CLI::App& hdprior);
Command addMatchCommand(CLI::App& hdprior);
Command addViewCommand(CLI::App& hdprior);
Command addDemoCommand(CLI::App& hdprior);
Command addEvalCommand(CLI::App& hdprior);
Command addMergeCommand(CLI::App& hdprior);
Command addDegradeTrajectoryCommand(CLI::App& hdprior);
Command addConfigCommand(CLI::App& hdprior);
Command addPlotCommand(CLI::App& hdprior);
Command addChangesCommand(CLI::App& hdprior);

}  // namespace hdprior::app
