#include "app/common_options.h"

#include "engine/error.h"
#include "engine/odom/odometry_drift.h"

namespace hdprior::app {

Config configOption(const CommandLine& cl) {
  Config config = cl.value("config") ? loadConfig(*cl.value("config")) : Config{};
  if (const auto drift = cl.value("odometry-drift")) config.odometry.drift = parseOdometryDrift(*drift, "option --odometry-drift");
  return config;
}

std::filesystem::path outputFolder(const std::filesystem::path& out) {
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out)) throw Error(out.string(), "exists and is not a folder");
  return out;
}

}  // namespace hdprior::app
