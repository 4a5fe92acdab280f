#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <vector>
#include <optional>
#include <string>

#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/map/hd_map.h"
#include "engine/map/ndt_grid.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

// Sliders over doubles; true when changed.
bool slider(const char* label, double& value, double min, double max, const char* format = "%.2f") {
  float v = float(value);
  if (!ImGui::SliderFloat(label, &v, float(min), float(max), format)) return false;
  value = v;
  return true;
}
bool sliderInt(const char* label, int& value, int min, int max) { return ImGui::SliderInt(label, &value, min, max); }

// The cell sizes the map carries, each a checkbox; the match runs coarse to fine over the ticked ones.
bool drawCellSizes(AppState& state) {
  MatchOptions& m = state.bench().config.match;
  bool changed = false;
  ImGui::Text("cell sizes");
  for (double size : tuningCellSizes(state.bench().config)) {
    const auto it = std::find(m.cellSizes.begin(), m.cellSizes.end(), size);
    bool on = it != m.cellSizes.end();
    ImGui::SameLine();
    char label[32];  // %g of a double can take 13 characters
    std::snprintf(label, sizeof label, "%g##cell", size);
    if (ImGui::Checkbox(label, &on)) {
      if (on) m.cellSizes.push_back(size);
      else if (m.cellSizes.size() > 1) m.cellSizes.erase(it);
      std::sort(m.cellSizes.begin(), m.cellSizes.end(), std::greater<>());
      changed = true;
    }
  }
  return changed;
}

bool drawMatcher(AppState& state) {
  MatchOptions& m = state.bench().config.match;
  bool changed = drawCellSizes(state);
  int backend = int(m.backend);
  const char* backends[] = {"ndt2d", "pcl"};
  if (ImGui::Combo("backend", &backend, backends, 2)) m.backend = MatchBackend(backend), changed = true;
  changed |= slider("outlier ratio", m.outlierRatio, 0.05, 0.95);
  changed |= sliderInt("iterations", m.maxIterations, 1, 100);
  changed |= slider("time budget (ms)", m.timeBudgetMs, 1.0, 500.0, "%.0f");
  changed |= slider("curb huber (m)", m.curbHuber, 0.01, 1.0);
  changed |= slider("curb max dist (m)", m.curbMaxDistance, 0.1, 3.0);
  return changed;
}

bool drawAcceptance(AppState& state) {
  MatchOptions& m = state.bench().config.match;
  bool changed = false;
  changed |= sliderInt("min points", m.minPoints, 10, 2000);
  changed |= slider("min inlier ratio", m.minInlierRatio, 0.0, 1.0);
  changed |= slider("degenerate ratio", m.degenerateRatio, 0.0, 0.5, "%.3f");
  changed |= slider("min information", m.minInformation, 0.0, 50.0, "%.1f");
  changed |= slider("gate chi2", m.gateChi2, 1.0, 50.0, "%.1f");
  changed |= slider("prediction sigma x", m.predictionSigma.x(), 0.05, 5.0);
  changed |= slider("prediction sigma y", m.predictionSigma.y(), 0.05, 5.0);
  changed |= slider("prediction sigma yaw (deg)", m.predictionSigma.z(), 0.1, 20.0);
  return changed;
}

bool drawRoadPoints(AppState& state) {
  SweepRoadPointOptions& r = state.bench().config.roadPoints;
  bool changed = false;
  changed |= slider("thin cell (m)", r.thinCell, 0.0, 1.0);
  changed |= slider("max range (m)", r.road.maxRange, 5.0, 80.0, "%.0f");
  changed |= slider("curb step (m)", r.road.maxStep, 0.01, 0.3, "%.3f");
  changed |= slider("step per metre", r.road.stepPerMetre, 0.0, 0.05, "%.3f");
  changed |= slider("max gap (m)", r.road.maxGap, 0.5, 20.0, "%.1f");
  changed |= slider("gutter rise (m)", r.road.gutterRise, 0.0, 0.1, "%.3f");
  changed |= slider("seed tolerance (m)", r.road.seedTolerance, 0.02, 0.5, "%.2f");
  changed |= slider("ground plane dist (m)", r.ground.planeDistance, 0.02, 0.5, "%.2f");
  changed |= slider("ground max tilt (deg)", r.ground.maxTiltDeg, 2.0, 45.0, "%.0f");
  return changed;
}

bool drawStartAndLandscape(AppState& state) {
  TuningBench& bench = state.bench();
  bool changed = false;
  ImGui::Text("start offset (from the run's prediction)");
  changed |= slider("forward (m)", bench.startOffset.x(), -5.0, 5.0);
  changed |= slider("left (m)", bench.startOffset.y(), -5.0, 5.0);
  double yawDeg = bench.startOffset.z() / kDegree;
  if (slider("yaw (deg)", yawDeg, -10.0, 10.0, "%.1f")) bench.startOffset.z() = yawDeg * kDegree, changed = true;
  changed |= ImGui::Checkbox("cost landscape", &bench.landscapeEnabled);
  if (bench.landscapeEnabled) {
    changed |= slider("half extent (m)", bench.landscapeOptions.halfExtent, 0.5, 10.0, "%.1f");
    changed |= slider("grid step (m)", bench.landscapeOptions.step, 0.05, 0.5);
  }
  return changed;
}

void drawResult(AppState& state) {
  const auto& inspection = state.bench().inspection();
  if (!inspection) {
    ImGui::TextDisabled("no keyframe matched yet");
    return;
  }
  const MatchResult& r = inspection->match;
  ImGui::Text("keyframe %zu (frame %zu): %s", inspection->keyframe, inspection->frame, toString(r.status));
  if (!r.reason.empty()) ImGui::TextWrapped("%s", r.reason.c_str());
  ImGui::Text("score %.1f (%.3f / point), inliers %.2f", r.score, r.scorePerPoint, r.inlierRatio);
  ImGui::Text("%zu points, %d iterations, %.1f ms", r.points, r.iterations, r.timeMs);
  ImGui::TextDisabled("(yaw in degrees) road points + match %.0f ms", state.bench().matchMs);
  if (state.bench().landscapePending()) {
    ImGui::TextDisabled("landscape ...");
  } else if (state.bench().analysis().landscape) {
    ImGui::TextDisabled("landscape %.0f ms", state.bench().landscapeMs);
  }
  if (inspection->truth) {
    const Eigen::Vector3d e = planarError(*inspection->truth, r.estimate);
    const Eigen::Vector3d e0 = planarError(*inspection->truth, inspection->start);
    ImGui::Text("error  along %.3f  lateral %.3f m  yaw %.2f", e.x(), e.y(), e.z() / kDegree);
    ImGui::TextDisabled("start  along %.2f  lateral %.2f m  yaw %.2f", e0.x(), e0.y(), e0.z() / kDegree);
  }
}

// The landscape's score over yaw at the estimate's (x, y): a flat curve is an unobserved heading.
void drawYawProfile(AppState& state) {
  const auto& landscape = state.bench().analysis().landscape;
  if (!landscape || landscape->yawScores.empty()) return;
  std::vector<float> values(landscape->yawScores.begin(), landscape->yawScores.end());
  char label[64];
  std::snprintf(label, sizeof label, "score over yaw +-%.0f deg", landscape->options.yawHalfDeg);
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  ImGui::PlotLines("##yaw", values.data(), int(values.size()), 0, label, *lo, *hi, ImVec2(ImGui::GetContentRegionAvail().x, 60));
}

// Every re-match: what changed, then what came out; a click restores the row's parameters.
void drawHistory(AppState& state) {
  TuningBench& bench = state.bench();
  const auto& rows = bench.history.rows();
  ImGui::BeginChild("history", ImVec2(0, 160), true);
  std::optional<size_t> restore;
  for (size_t i = rows.size(); i-- > 0;) {
    const MatchHistoryRow& r = rows[i];
    std::string changes;
    for (const std::string& c : r.changes) changes += (changes.empty() ? "" : "; ") + c;
    char result[160];
    if (r.error)
      std::snprintf(result, sizeof result, "%s, score %.1f, error %.2f / %.2f m / %.2f deg", r.constraint.c_str(), r.score,
                    r.error->x(), r.error->y(), r.error->z() / kDegree);
    else
      std::snprintf(result, sizeof result, "%s, score %.1f", r.constraint.c_str(), r.score);
    const std::string label = std::to_string(i) + "  kf " + std::to_string(r.keyframe) + "  " + changes + "\n    " + result + "##h" + std::to_string(i);
    if (ImGui::Selectable(label.c_str(), false)) restore = i;
  }
  ImGui::EndChild();
  if (restore) bench.restoreHistory(*restore);
}

void drawConfigFile(AppState& state) {
  TuningBench& bench = state.bench();
  char path[512];
  std::snprintf(path, sizeof path, "%s", bench.configPath.string().c_str());
  ImGui::SetNextItemWidth(-110);
  if (ImGui::InputText("##config", path, sizeof path)) bench.configPath = path;
  ImGui::SameLine();
  if (ImGui::Button("Save")) bench.saveConfig();
  ImGui::SameLine();
  if (ImGui::Button("Load")) bench.loadConfig();
}

}  // namespace

void drawNdtTab(AppState& state) {
  TuningBench& bench = state.bench();
  const bool ready = bench.runner().session() && bench.keyframeCount() > 0;
  if (!ready) ImGui::TextDisabled("run or step the pipeline to have keyframes to match");
  else {
    if (ImGui::Button("Match this keyframe")) state.matchKeyframeAtFrame();
    ImGui::SameLine();
    ImGui::Checkbox("on change", &state.autoMatch);
    ImGui::SameLine();
    ImGui::Checkbox("focus", &state.focusOnMatch);
  }
  drawResult(state);
  drawYawProfile(state);
  ImGui::PushItemWidth(150);
  bool changed = false;
  if (ImGui::CollapsingHeader("Matcher", ImGuiTreeNodeFlags_DefaultOpen)) changed |= drawMatcher(state);
  if (ImGui::CollapsingHeader("Start and landscape", ImGuiTreeNodeFlags_DefaultOpen)) changed |= drawStartAndLandscape(state);
  if (ImGui::CollapsingHeader("Acceptance")) changed |= drawAcceptance(state);
  if (ImGui::CollapsingHeader("Road points")) changed |= drawRoadPoints(state);
  ImGui::PopItemWidth();
  if (ImGui::CollapsingHeader("Config file", ImGuiTreeNodeFlags_DefaultOpen)) drawConfigFile(state);
  if (ImGui::CollapsingHeader("History (click: restore)", ImGuiTreeNodeFlags_DefaultOpen)) drawHistory(state);
  if (!bench.message.empty()) ImGui::TextWrapped("%s", bench.message.c_str());
  if (changed && ready && state.autoMatch && bench.selected()) bench.matchSelected();
}

}  // namespace hdprior::ui
