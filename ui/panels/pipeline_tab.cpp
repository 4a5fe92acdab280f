#include <imgui.h>
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);

void drawRunControls(AppState& state) {
  TuningBench& bench = state.bench();
  SessionRunner& runner = bench.runner();
  if (runner.busy()) {
    ImGui::ProgressBar(runner.progress(), ImVec2(-90, 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(-1, 0))) runner.cancel();
    ImGui::TextDisabled("%s ...", runner.jobName().c_str());
    return;
  }
  if (ImGui::Button("Run pipeline")) bench.run();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a new session with the tuned configuration, every sweep, then the batch solve");
  ImGui::SameLine();
  if (ImGui::Button("Step keyframe")) bench.stepKeyframe();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the session to its next keyframe: odometry, match, prior, incremental solve");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) bench.reset();
  ImGui::SameLine();
  if (bench.mapCheckPending()) ImGui::TextDisabled("checking the map ...");
  else if (ImGui::Button("Check map")) bench.checkMap();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("after a run: the lidar's road against the map's drivable area along the final trajectory "
                      "(hdprior changes): the changes layer and map-change events");
  if (!runner.lastJob().empty()) ImGui::TextWrapped("%s", runner.lastJob().c_str());
  if (!runner.error().empty()) ImGui::TextColored(kErrorColor, "%s", runner.error().c_str());
}

// A text field over a std::string (no file dialog in the app: paths are typed or pasted).
bool pathField(const char* id, std::string& path) {
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%s", path.c_str());
  ImGui::SetNextItemWidth(-70);
  const bool entered = ImGui::InputText(id, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  path = buffer;
  return entered;
}

// The odometry file: opened here, drawn as the file_trajectory layer, run over as `run --odometry`.
void drawOdometryFile(TuningBench& bench) {
  OdometryFile& file = bench.odometryFile;
  ImGui::TextUnformatted("Odometry from a trajectory file (TUM or KITTI)");
  const bool entered = pathField("##odometry_file", file.path);
  ImGui::SameLine();
  const bool open = ImGui::Button("Open", ImVec2(-1, 0)) || entered;
  int format = int(file.format), frame = int(file.frame);
  ImGui::SetNextItemWidth(90);
  ImGui::Combo("format", &format, "auto\0tum\0kitti\0");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  ImGui::Combo("frame", &frame, "first\0city\0");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("first: the file's pose at the first sweep is put on the first true pose; city: the poses are city_T_ego");
  file.format = OdometryFile::Format(format);
  file.frame = GivenOdometryFrame(frame);
  if (file.format != OdometryFile::Format::Tum) {
    ImGui::TextDisabled("KITTI times file (optional: else one line per sweep)");
    pathField("##odometry_times", file.times);
  }
  if (open) bench.openOdometryFile();
  if (!file.error().empty()) ImGui::TextColored(kErrorColor, "%s", file.error().c_str());
  if (!file.isOpen()) return;
  const GivenOdometry& given = *file.given();
  ImGui::Text("%zu poses, %s, frame %s", given.trajectory.size(), trajectoryFormatName(given.format), givenOdometryFrameName(given.frame));
  ImGui::SameLine();
  if (ImGui::SmallButton("Close")) bench.closeOdometryFile();
  ImGui::Checkbox("use it as the odometry (else the built-in)", &file.use);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Run, Step keyframe and Reset start a session over the file, as hdprior run --odometry FILE");
}

void drawSessionSummary(AppState& state) {
  const Session* session = state.bench().runner().session();
  if (!session) {
    ImGui::TextDisabled("no session yet: run the pipeline or step it");
    return;
  }
  ImGui::Text("sweeps %zu / %zu   keyframes %zu", session->sweepsDone(), session->sweepCount(),
              session->odometry().keyframes().size());
  ImGui::TextWrapped("odometry: %s", odometrySourceText(*session).c_str());
  for (const SkippedSweep& s : session->skippedSweeps()) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.2f, 1.0f), "skipped sweep %zu (unreadable): %s", s.index, s.problem.c_str());
  }
  ImGui::TextWrapped("priors: %s", constraintSummary(constraintsOf(session->matches())).c_str());
  const StageTimes& t = session->times();
  ImGui::Text("time: odometry %.1f s, road points %.1f s", t.odometryS, t.roadPointsS);
  ImGui::Text("      match %.1f s, graph %.1f s", t.matchS, t.graphS);
  const auto& analysis = state.bench().analysis();
  ImGui::Text("ATE rmse: odometry %.3f m, optimised %.3f m", finiteRmse(analysis.odometryError), finiteRmse(analysis.optimizedError));
}

}  // namespace

void drawPipelineTab(AppState& state) {
  drawOdometryFile(state.bench());
  ImGui::Separator();
  drawRunControls(state);
  ImGui::Separator();
  drawSessionSummary(state);
}

}  // namespace hdprior::ui
