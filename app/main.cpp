#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/parse_error_line.h"
#include "engine/allocator_tuning.h"
#include "engine/error.h"

namespace {

using hdprior::app::Command;

std::vector<Command> addCommands(CLI::App& hdprior) {
  using namespace hdprior::app;
  std::vector<Command> commands;
  for (auto add : {addInfoCommand, addExportMapCommand, addRunCommand, addEvalCommand, addMergeCommand,
                   addDegradeTrajectoryCommand, addDemoCommand, addSimCommand, addMatchCommand, addSnapshotCommand,
                   addPlotCommand, addViewCommand, addConfigCommand, addChangesCommand}) {
    commands.push_back(add(hdprior));
  }
  return commands;
}

const Command* findCommand(const std::vector<Command>& commands, const std::string& name) {
  for (const Command& c : commands) {
    if (c.parser->get_name() == name) return &c;
  }
  return nullptr;
}

// The command's work, its errors as one line each.
int runCommand(const Command& command) {
  const std::string name = command.parser->get_name();
  try {
    return command.run();
  } catch (const hdprior::Error& e) {
    std::fprintf(stderr, "hdprior %s: %s\n", name.c_str(), e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "hdprior %s: out of memory\n", name.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hdprior %s: internal error: %s\n", name.c_str(), e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  hdprior::keepFreedMemoryMapped();
  CLI::App hdprior("hdprior: globally consistent lidar trajectories and maps from HD-map priors", "hdprior");
  hdprior.set_version_flag("--version", "hdprior " HDPRIOR_VERSION);
  hdprior.require_subcommand(1);
  hdprior.footer("`hdprior COMMAND --help` shows a command's options and their defaults.");
  hdprior.get_formatter()->column_width(36);
  // Every option's default shows in --help; an option given twice keeps its last value.
  hdprior.option_defaults()->always_capture_default()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  const std::vector<Command> commands = addCommands(hdprior);

  if (argc < 2) {
    std::fputs(hdprior.help().c_str(), stderr);
    return 2;
  }
  const std::string first = argv[1];
  const Command* command = findCommand(commands, first);
  if (!command && first != "-h" && first != "--help" && first != "--version") {
    if (first.rfind('-', 0) == 0) std::fprintf(stderr, "hdprior: option %s: unknown option (try hdprior --help)\n", first.c_str());
    else std::fprintf(stderr, "hdprior: unknown command '%s' (try hdprior --help)\n", first.c_str());
    return 2;
  }
  try {
    hdprior.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return hdprior.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    const std::string name = command ? "hdprior " + first : std::string("hdprior");
    std::fprintf(stderr, "%s: %s (try %s --help)\n", name.c_str(), hdprior::app::parseErrorLine(e).c_str(), name.c_str());
    return 2;
  }
  // Parsing succeeds only with a subcommand, and the subcommand came first (--help and --version
  // end in CLI::Success above).
  return runCommand(*command);
}
