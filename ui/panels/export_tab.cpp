#include <imgui.h>

#include <cstdio>
#include <filesystem>

#include "engine/error.h"
#include "engine/io/tum_trajectory.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

void writeTrajectories(AppState& state, const std::filesystem::path& dir) {
  const render::Analysis& a = state.bench().analysis();
  try {
    std::filesystem::create_directories(dir);
    size_t written = 0;
    for (const auto& [name, trajectory] : {std::pair{"groundtruth.tum", &a.groundTruth}, std::pair{"odometry.tum", &a.odometry},
                                           std::pair{"optimized.tum", &a.optimized}}) {
      if (trajectory->empty()) continue;
      writeTum(dir / name, *trajectory);
      ++written;
    }
    state.bench().message = "wrote " + std::to_string(written) + " trajectories to " + dir.string();
  } catch (const Error& e) {
    state.bench().message = e.what();
  } catch (const std::filesystem::filesystem_error& e) {
    state.bench().message = e.what();
  }
}

// Save session writes the view (frame, camera, layers, tab, plots, bookmarks, runs A and B) to a
// file that `hdprior view LOG --session FILE` and `hdprior snapshot --session FILE` restore.
void drawSession(AppState& state) {
  static char file[512] = "session.json";
  ImGui::Separator();
  ImGui::SetNextItemWidth(-200);
  ImGui::InputText("##session", file, sizeof file);
  ImGui::SameLine();
  try {
    if (ImGui::Button("Save session")) {
      writeViewSession(file, state.session());
      state.bench().message = std::string("wrote ") + file;
    }
    ImGui::SameLine();
    if (ImGui::Button("Load session")) state.restore(readViewSession(file));
  } catch (const Error& e) {
    state.bench().message = e.what();
  }
}

}  // namespace

void drawExportTab(AppState& state) {
  TuningBench& bench = state.bench();
  char dir[512];
  std::snprintf(dir, sizeof dir, "%s", bench.exportDir.string().c_str());
  ImGui::SetNextItemWidth(-1);
  if (ImGui::InputText("##dir", dir, sizeof dir)) bench.exportDir = dir;
  ImGui::TextDisabled("folder the files below go to");
  const std::filesystem::path& folder = bench.exportDir;
  if (ImGui::Button("View to PNG (view.png)")) state.requestScreenshot(folder / "view.png");
  const bool ready = bench.runner().session() != nullptr && !bench.analysis().odometry.empty();
  ImGui::BeginDisabled(!ready);
  if (ImGui::Button("Trajectories to TUM")) writeTrajectories(state, folder);
  if (ImGui::Button("Map to PLY (map.ply, 0.2 m voxels)")) {
    std::error_code ignored;
    std::filesystem::create_directories(folder, ignored);
    bench.runner().exportMap(folder / "map.ply", 0.2);
  }
  ImGui::EndDisabled();
  if (ImGui::Button("Tuned config (config.json)")) {
    std::error_code ignored;
    std::filesystem::create_directories(folder, ignored);
    bench.configPath = folder / "config.json";
    bench.saveConfig();
  }
  drawSession(state);
  if (!bench.message.empty()) ImGui::TextWrapped("%s", bench.message.c_str());
  if (!bench.runner().lastJob().empty()) ImGui::TextWrapped("%s", bench.runner().lastJob().c_str());
}

}  // namespace hdprior::ui
