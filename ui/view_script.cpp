#include "ui/view_script.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/pipeline/diagnostic_plots.h"
#include "render/layer_registry.h"
#include "ui/playback.h"

namespace hdprior::ui {
namespace {

bool isInteger(const std::string& s) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

bool isUnitFraction(const std::string& s) {
  try {
    size_t used = 0;
    const double v = std::stod(s, &used);
    return used == s.size() && v >= 0.0 && v <= 1.0;
  } catch (const std::exception&) {
    return false;
  }
}

bool isNumber(const std::string& s) {
  try {
    size_t used = 0;
    const double v = std::stod(s, &used);
    return used == s.size() && std::isfinite(v);
  } catch (const std::exception&) {
    return false;
  }
}

bool isLayer(const std::string& s) {
  const auto& names = render::layerNames();
  return std::find(names.begin(), names.end(), s) != names.end();
}

// Why the arguments are wrong for the verb; empty when they are fine.
std::string checkArguments(const std::string& verb, const std::vector<std::string>& a) {
  static const std::map<std::string, std::pair<size_t, size_t>> arity = {
      {"frame", {1, 1}}, {"step", {1, 1}}, {"play", {1, 1}}, {"pause", {0, 0}}, {"view", {1, 1}}, {"layer", {2, 2}},
      {"opacity", {2, 2}}, {"wait", {1, 1}}, {"screenshot", {1, 1}}, {"exit", {0, 0}}, {"run", {0, 0}},
      {"step-keyframe", {0, 0}}, {"keyframe", {1, 1}}, {"match", {0, 0}}, {"optimize", {0, 0}}, {"check-map", {0, 0}}, {"offset", {3, 3}},
      {"tab", {1, 1}}, {"report", {0, 0}}, {"odometry", {1, 3}}, {"use-odometry", {1, 1}}, {"plot", {2, 2}},
      {"events", {0, 0}}, {"next-event", {0, 0}}, {"prev-event", {0, 0}}, {"bookmark", {1, 64}}, {"compare", {1, 1}},
      {"measure", {1, 4}}, {"pick", {2, 2}}, {"save-session", {1, 1}}, {"load-session", {1, 1}},
      {"ground-labels", {2, 2}}};
  const auto it = arity.find(verb);
  if (it == arity.end()) return "unknown command '" + verb + "'";
  const auto [least, most] = it->second;
  if (a.size() < least || a.size() > most)
    return "'" + verb + "' takes " + std::to_string(least) + (least == most ? "" : " to " + std::to_string(most)) + " argument(s)";
  if ((verb == "frame" || verb == "wait") && (!isInteger(a[0]) || a[0][0] == '-'))
    return "'" + verb + "' needs a non-negative integer";
  if (verb == "ground-labels" && (!isInteger(a[1]) || a[1][0] == '-')) return "'ground-labels' needs FILE and a non-negative frame";
  if (verb == "step" && !isInteger(a[0])) return "'step' needs an integer";
  if (verb == "play" &&
      std::none_of(Playback::kSpeedNames.begin(), Playback::kSpeedNames.end(), [&](const char* n) { return a[0] == n; }))
    return "'play' needs 1x, 2x, 5x or max";
  if (verb == "view" && a[0] != "top" && a[0] != "orbit") return "'view' needs top or orbit";
  if ((verb == "layer" || verb == "opacity") && !isLayer(a[0])) return "unknown layer '" + a[0] + "'";
  if (verb == "layer" && a[1] != "on" && a[1] != "off" && a[1] != "toggle") return "'layer' needs on, off or toggle";
  if (verb == "opacity" && !isUnitFraction(a[1])) return "'opacity' needs a value in 0..1";
  if (verb == "keyframe" && (!isInteger(a[0]) || a[0][0] == '-')) return "'keyframe' needs a non-negative integer";
  if (verb == "offset" && !std::all_of(a.begin(), a.end(), isNumber)) return "'offset' needs three numbers";
  if (verb == "tab" && std::find(kBenchTabs.begin(), kBenchTabs.end(), a[0]) == kBenchTabs.end())
    return "'tab' needs Pipeline, NDT, PGO, Keyframe, Events, Compare or Export";
  if (verb == "plot" && !findDiagnosticPlot(a[0])) return "unknown plot '" + a[0] + "' (" + diagnosticPlotNames() + ")";
  if (verb == "plot" && a[1] != "on" && a[1] != "off") return "'plot' needs on or off";
  if (verb == "odometry" && a.size() > 1 && a[1] != "auto" && a[1] != "tum" && a[1] != "kitti")
    return "'odometry' needs the format auto, tum or kitti";
  if (verb == "odometry" && a.size() > 2 && a[2] != "first" && a[2] != "city") return "'odometry' needs the frame first or city";
  if (verb == "use-odometry" && a[0] != "file" && a[0] != "builtin") return "'use-odometry' needs file or builtin";
  if (verb == "measure" && !(a.size() == 4 && std::all_of(a.begin(), a.end(), isNumber)) && !(a.size() == 1 && a[0] == "match"))
    return "'measure' needs four numbers (X1 Y1 X2 Y2, city metres) or 'match'";
  if (verb == "pick" && !std::all_of(a.begin(), a.end(), isNumber)) return "'pick' needs two numbers (X Y, city metres)";
  return "";
}

}  // namespace

std::vector<ScriptCommand> parseViewScript(const std::string& text, const std::string& source) {
  std::vector<ScriptCommand> commands;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    ScriptCommand command;
    command.line = number;
    if (!(words >> command.verb)) continue;
    for (std::string word; words >> word;) command.args.push_back(word);
    if (const std::string problem = checkArguments(command.verb, command.args); !problem.empty())
      throw Error(source, "line " + std::to_string(number) + ": " + problem);
    commands.push_back(std::move(command));
  }
  return commands;
}

std::vector<ScriptCommand> readViewScript(const std::filesystem::path& file) {
  return parseViewScript(readFileText(file), file.string());
}

}  // namespace hdprior::ui
