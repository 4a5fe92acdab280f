#include "ui/panels/bench_panel.h"

#include <imgui.h>

#include "ui/app_state.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {

void drawBenchPanel(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kBenchPanelWidth, 0));
  ImGui::SetNextWindowSize(ImVec2(kBenchPanelWidth, io.DisplaySize.y - kStatusBarHeight - kTimelineHeight));
  ImGui::Begin("Bench", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  if (ImGui::BeginTabBar("bench")) {
    const struct {
      const char* name;
      void (*draw)(AppState&);
    } tabs[] = {{"Pipeline", drawPipelineTab}, {"NDT", drawNdtTab}, {"PGO", drawPgoTab},
                {"Keyframe", drawKeyframeTab}, {"Events", drawEventsTab}, {"Compare", drawCompareTab},
                {"Export", drawExportTab}};
    for (const auto& tab : tabs) {
      const bool select = state.selectTab == tab.name;
      if (ImGui::BeginTabItem(tab.name, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0)) {
        state.currentTab = tab.name;
        tab.draw(state);
        ImGui::EndTabItem();
      }
    }
    state.selectTab.clear();
    ImGui::EndTabBar();
  }
  ImGui::End();
}

}  // namespace hdprior::ui
