#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "engine/error.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/config_schema.h"

namespace hdprior::app {
namespace {

struct ConfigCommandArguments {
  bool defaults = false;
  bool reference = false;
  std::string check;
};

int runConfig(const ConfigCommandArguments& a) {
  if (int(a.defaults) + int(a.reference) + int(!a.check.empty()) != 1) {
    throw Error("option --defaults/--reference/--check", "give exactly one of --defaults, --reference and --check FILE");
  }
  if (a.defaults || a.reference) {
    std::fputs((a.defaults ? formatConfig(defaultConfig()) : configReference()).c_str(), stdout);
    return 0;
  }
  loadConfig(a.check);  // a problem is an Error naming the file and the key: one line, exit 2
  std::printf("%s: a valid configuration\n", a.check.c_str());
  return 0;
}

}  // namespace

Command addConfigCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand("config", "the configuration: print the defaults or the reference, or check a file");
  auto a = std::make_shared<ConfigCommandArguments>();
  CLI::Option* defaults = command->add_flag("--defaults", a->defaults,
                                            "print the default configuration (every key; a file needs only the keys it changes)");
  CLI::Option* reference = command->add_flag("--reference", a->reference,
                                             "print the reference of every key (default, range, unit, what it does) in Markdown")->excludes(defaults);
  command->add_option("--check", a->check, "check a configuration file: unknown keys, types and ranges")
      ->type_name("FILE")->excludes(defaults)->excludes(reference);
  return {command, [a] { return runConfig(*a); }};
}

}  // namespace hdprior::app
