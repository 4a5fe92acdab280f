#include <imgui.h>
#include <cmath>

#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

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
  if (ImGui::Button("Reset")) bench.runner().restart(bench.config);
  if (!runner.lastJob().empty()) ImGui::TextWrapped("%s", runner.lastJob().c_str());
  if (!runner.error().empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", runner.error().c_str());
}

void drawSessionSummary(AppState& state) {
  const Session* session = state.bench().runner().session();
  if (!session) {
    ImGui::TextDisabled("no session yet: run the pipeline or step it");
    return;
  }
  ImGui::Text("sweeps %zu / %zu   keyframes %zu", session->sweepsDone(), session->sweepCount(),
              session->odometry().keyframes().size());
  for (const SkippedSweep& s : session->skippedSweeps()) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.2f, 1.0f), "skipped sweep %zu (unreadable): %s", s.index, s.problem.c_str());
  }
  size_t counts[3] = {0, 0, 0};
  for (const KeyframeMatch& m : session->matches()) ++counts[int(m.match.status)];
  ImGui::Text("matches: %zu accepted, %zu degenerate, %zu rejected", counts[0], counts[1], counts[2]);
  const StageTimes& t = session->times();
  ImGui::Text("time: odometry %.1f s, road points %.1f s", t.odometryS, t.roadPointsS);
  ImGui::Text("      match %.1f s, graph %.1f s", t.matchS, t.graphS);
  const auto& analysis = state.bench().analysis();
  ImGui::Text("ATE rmse: odometry %.3f m, optimised %.3f m", finiteRmse(analysis.odometryError), finiteRmse(analysis.optimizedError));
}

}  // namespace

void drawPipelineTab(AppState& state) {
  drawRunControls(state);
  ImGui::Separator();
  drawSessionSummary(state);
}

}  // namespace hdprior::ui
