#include "app/common_options.h"

#include "engine/error.h"

namespace hdprior::app {

Config configOption(const CommandLine& cl) { return cl.value("config") ? loadConfig(*cl.value("config")) : Config{}; }

std::filesystem::path outputFolder(const std::filesystem::path& out) {
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out)) throw Error(out.string(), "exists and is not a folder");
  return out;
}

}  // namespace hdprior::app
