#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace hdprior::ui {

// One step of a scripted `hdprior view` session. A script is a text file, one command a line,
// '#' starts a comment:
//   frame N                     go to frame N (clamped to the log)
//   step N                      N frames forward (negative: back), clamped
//   play 1x|2x|5x|max  /  pause
//   view top|orbit
//   layer NAME on|off|toggle
//   opacity NAME VALUE          0..1
//   wait N                      draw N frames
//   screenshot FILE.png         the window as drawn, panels included
//   exit
struct ScriptCommand {
  std::string verb;
  std::vector<std::string> args;
  int line = 0;
};

// Reads and checks a script (verbs, argument counts and values, layer names) before anything
// runs; throws Error(file, "line N: ...").
std::vector<ScriptCommand> readViewScript(const std::filesystem::path& file);
std::vector<ScriptCommand> parseViewScript(const std::string& text, const std::string& source);

}  // namespace hdprior::ui
