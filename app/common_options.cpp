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

OdometryFileOptions odometryFileOptions(const CommandLine& cl, const std::string& sourceOption) {
  OdometryFileOptions o;
  for (const char* name : {"odometry-format", "odometry-frame", "odometry-times"}) {
    if (cl.has(name) && !cl.has(sourceOption)) throw Error(std::string("option --") + name, "needs --" + sourceOption);
  }
  if (const auto f = cl.value("odometry-format")) o.format = parseTrajectoryFormat(*f, "option --odometry-format");
  if (const auto f = cl.value("odometry-frame")) o.frame = parseGivenOdometryFrame(*f, "option --odometry-frame");
  if (const auto t = cl.value("odometry-times")) o.times = *t;
  return o;
}

}  // namespace hdprior::app
