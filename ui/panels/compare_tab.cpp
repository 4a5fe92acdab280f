#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/colormap.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

void startControls(AppState& state) {
  TuningBench& bench = state.bench();
  static char file[512] = "b.json";
  ImGui::TextWrapped("Run B over the same log with other parameters; both trajectories, matches and plots show together.");
  ImGui::BeginDisabled(bench.comparison().busy());
  if (ImGui::Button("Run B with the bench's parameters")) bench.compare(bench.config, "bench parameters");
  ImGui::SetNextItemWidth(200);
  ImGui::InputText("##bfile", file, sizeof file);
  ImGui::SameLine();
  if (ImGui::Button("Run B from file")) bench.compareFile(file);
  ImGui::EndDisabled();
  if (bench.comparison().active() && !bench.comparison().busy() && ImGui::Button("Clear B")) bench.clearComparison();
  if (bench.comparison().busy()) ImGui::ProgressBar(bench.comparison().progress(), ImVec2(-1, 0), "running B");
  if (!bench.comparison().error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "B: %s", bench.comparison().error().c_str());
}

// A's column before A has run.
RunSummary notRun() {
  RunSummary s;
  s.ate.mean = s.ate.rmse = s.ate.max = s.pipelineS = NAN;
  return s;
}

size_t countOf(const RunSummary& s, const std::string& category) {
  for (const auto& [name, n] : s.constraints)
    if (name == category) return n;
  return 0;
}

void row(const char* label, double a, double b, const char* format) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(label);
  for (double v : {a, b, b - a}) {
    ImGui::TableNextColumn();
    if (std::isfinite(v)) ImGui::Text(format, v);
    else ImGui::TextDisabled("-");
  }
}

// A against B: ATE mean / rmse / max, what the priors fix, keyframes, time.
void differenceTable(const RunSummary& a, const RunSummary& b) {
  if (!ImGui::BeginTable("ab", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) return;
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 110.0f);
  for (const char* h : {"A", "B", "B - A"}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  row("ATE mean m", a.ate.mean, b.ate.mean, "%.4f");
  row("ATE rmse m", a.ate.rmse, b.ate.rmse, "%.4f");
  row("ATE max m", a.ate.max, b.ate.max, "%.4f");
  row("keyframes", double(a.keyframes), double(b.keyframes), "%.0f");
  for (const std::string& c : constraintCategories())
    if (countOf(a, c) + countOf(b, c) > 0) row(c.c_str(), double(countOf(a, c)), double(countOf(b, c)), "%.0f");
  row("time (s)", a.pipelineS, b.pipelineS, "%.2f");
  ImGui::EndTable();
}

// A cost landscape as a heat map in [min, max] (Turbo, lowest blue), the estimate at its centre.
void drawLandscape(const CostLandscape& l, ImVec2 min, float side) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const auto [lo, hi] = std::minmax_element(l.scores.begin(), l.scores.end());
  const float cell = side / float(l.size);
  for (int r = 0; r < l.size; ++r)
    for (int c = 0; c < l.size; ++c) {
      const float t = float((l.at(r, c) - *lo) / std::max(*hi - *lo, 1e-12));
      const Eigen::Vector3f rgb = render::turbo(t);
      const ImVec2 p(min.x + cell * float(c), min.y + side - cell * float(r + 1));  // north up
      draw->AddRectFilled(p, ImVec2(p.x + cell + 0.5f, p.y + cell + 0.5f), ImColor(rgb.x(), rgb.y(), rgb.z()));
    }
  const ImVec2 centre(min.x + side / 2, min.y + side / 2);
  draw->AddCircle(centre, 4.0f, IM_COL32(255, 255, 255, 255));
}

void landscapes(AppState& state) {
  const render::Analysis& a = state.bench().analysis();
  if (!a.comparison) return;
  ImGui::Separator();
  ImGui::TextWrapped("cost landscapes of the current keyframe, each around its estimate (circle)");
  const float side = (ImGui::GetContentRegionAvail().x - 12) / 2;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const struct {
    const char* name;
    const std::optional<CostLandscape>& landscape;
  } runs[] = {{"A", a.landscape}, {"B", a.comparison->landscape}};
  for (int i = 0; i < 2; ++i) {
    const ImVec2 min(origin.x + float(i) * (side + 12), origin.y + 16);
    ImGui::GetWindowDrawList()->AddText(ImVec2(min.x, origin.y), IM_COL32(220, 220, 220, 255), runs[i].name);
    if (runs[i].landscape && runs[i].landscape->size > 0) drawLandscape(*runs[i].landscape, min, side);
    else ImGui::GetWindowDrawList()->AddRect(min, ImVec2(min.x + side, min.y + side), IM_COL32(255, 255, 255, 60));
  }
  ImGui::Dummy(ImVec2(2 * side + 12, side + 20));
}

}  // namespace

void drawCompareTab(AppState& state) {
  startControls(state);
  TuningBench& bench = state.bench();
  const auto& b = bench.comparison().summary();
  if (!b) return;
  ImGui::Separator();
  ImGui::Text("A: this bench's run   B: %s", bench.comparison().name().c_str());
  if (!bench.summary()) ImGui::TextDisabled("run A (Pipeline tab) for its side of the table");
  differenceTable(bench.summary() ? *bench.summary() : notRun(), *b);
  landscapes(state);
}

}  // namespace hdprior::ui
