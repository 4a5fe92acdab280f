#pragma once
#include <array>
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
// The tuning bench (each waits for its work to finish):
//   run                         the pipeline over the whole log with the tuned config, optimised
//   step-keyframe               the session to its next keyframe
//   keyframe K                  select keyframe K, match it with the tuned options, go to its frame
//   match                       the same for the keyframe nearest the current frame
//   offset DX DY DYAW_DEG       the tuning panel's start offset (forward, left, yaw); re-matches
//   optimize                    "optimise now" with the tuned prior and graph options
//   tab Pipeline|NDT|PGO|Keyframe|Events|Compare|Export   bring a bench tab to the front
//   report                      print what the bench shows (odometry, match, solve, ATE) to stdout
//   odometry FILE [auto|tum|kitti] [first|city]   open a trajectory file as the odometry (the
//                               Pipeline tab's Open; a bad file stops the script with its error)
//   use-odometry file|builtin   the Pipeline tab's checkbox: the next run over the file or not
// The debugging bench:
//   plot NAME on|off            show or hide a Diagnostics plot (score, inliers, road_points, curb_points,
//                               sigma_along, sigma_lateral, sigma_yaw, chi2, residual, error_along,
//                               error_lateral, error_yaw, ate_along, ate_lateral)
//   events                      print the run's events: `event I keyframe K frame F KIND DETAIL`
//   next-event / prev-event     go to the next / previous event (N / Shift+N); prints `frame F`
//   bookmark NOTE...            a bookmark at the current frame (B)
//   compare FILE                run B with this configuration over the log (the Compare tab); waits for it;
//                               `report` then adds `compare: A ate_rmse X B ate_rmse Y`
//   measure X1 Y1 X2 Y2         measure between two ground points (city metres): prints
//                               `measure: distance D along A lateral L` (the ego heading's frame)
//   measure match               the same from the inspected match's estimate to the truth
//   pick X Y                    what lies at a city point: prints `pick: ...`
//   save-session FILE / load-session FILE   the view as a session file (load waits for its runs)
inline constexpr std::array<const char*, 7> kBenchTabs = {"Pipeline", "NDT", "PGO", "Keyframe", "Events", "Compare", "Export"};

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
