#include "app/common_options.h"

#include <CLI/CLI.hpp>

#include "app/option_checks.h"
#include "engine/error.h"
#include "engine/odom/odometry_drift.h"

namespace hdprior::app {

void addLogArgument(CLI::App& command, std::string& log) { command.add_option("LOG", log, "the log's folder")->required(); }

void addConfigOption(CLI::App& command, ConfigArguments& arguments) {
  command.add_option("--config", arguments.file, "the JSON configuration (default: the built-in one, `hdprior config --defaults`)")
      ->type_name("FILE");
}

void addOdometryDriftOption(CLI::App& command, ConfigArguments& arguments) {
  command
      .add_option("--odometry-drift", arguments.odometryDrift,
                  "degrade the odometry's reported poses reproducibly: scale error, yaw and pitch drift in degrees per 100 m "
                  "(replaces the configuration's odometry.drift)")
      ->type_name("SCALE,YAW_DEG_PER_100M[,PITCH_DEG_PER_100M]")
      ->check(parsedBy([](const std::string& text) { parseOdometryDrift(text, "option --odometry-drift"); }));
}

Config configOf(const ConfigArguments& arguments) {
  Config config = arguments.file.empty() ? defaultConfig() : loadConfig(arguments.file);
  if (!arguments.odometryDrift.empty()) config.odometry.drift = parseOdometryDrift(arguments.odometryDrift, "option --odometry-drift");
  return config;
}

std::filesystem::path outputFolder(const std::filesystem::path& out) {
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out)) throw Error(out.string(), "exists and is not a folder");
  return out;
}

void checkOutputFile(const std::filesystem::path& out) {
  const std::filesystem::path folder = out.parent_path().empty() ? "." : out.parent_path();
  if (!std::filesystem::is_directory(folder)) throw Error(out.string(), "its folder does not exist");
  if (std::filesystem::is_directory(out)) throw Error(out.string(), "is a directory, expected a .png file name");
}

void addOdometryFileOptions(CLI::App& command, OdometryFileArguments& arguments, CLI::Option* source) {
  command.add_option("--odometry-format", arguments.format, "the trajectory file's format (default: detected from its lines)")
      ->type_name("tum|kitti")
      ->check(parsedBy([](const std::string& text) { parseTrajectoryFormat(text, "option --odometry-format"); }))
      ->needs(source);
  command.add_option("--odometry-frame", arguments.frame, "the frame of the file's poses: the first pose's, or the city's")
      ->type_name("first|city")
      ->check(parsedBy([](const std::string& text) { parseGivenOdometryFrame(text, "option --odometry-frame"); }))
      ->needs(source);
}

void addOdometryTimesOption(CLI::App& command, OdometryFileArguments& arguments, CLI::Option* source) {
  command.add_option("--odometry-times", arguments.times, "a KITTI file's timestamps, one a line")->type_name("FILE")->needs(source);
}

void addGivenOdometryOptions(CLI::App& command, std::string& file, OdometryFileArguments& arguments, const std::string& help) {
  CLI::Option* odometry = command.add_option("--odometry", file, help)->type_name("FILE");
  addOdometryFileOptions(command, arguments, odometry);
  addOdometryTimesOption(command, arguments, odometry);
}

OdometryFileOptions odometryFileOptions(const OdometryFileArguments& arguments) {
  OdometryFileOptions o;
  if (!arguments.format.empty()) o.format = parseTrajectoryFormat(arguments.format, "option --odometry-format");
  o.frame = parseGivenOdometryFrame(arguments.frame, "option --odometry-frame");
  if (!arguments.times.empty()) o.times = arguments.times;
  return o;
}

}  // namespace hdprior::app
