#include <imgui.h>

#include <cmath>

#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

void sliderD(const char* label, double& value, double min, double max, const char* format = "%.2f") {
  float v = float(value);
  if (ImGui::SliderFloat(label, &v, float(min), float(max), format)) value = v;
}

void drawWeights(AppState& state) {
  PosePriorOptions& p = state.bench().config.prior;
  PoseGraphOptions& g = state.bench().config.graph;
  ImGui::PushItemWidth(150);
  ImGui::Text("HD-map priors");
  sliderD("altitude sigma (m)", p.altitudeSigma, 0.01, 1.0);
  double egoHeight = p.egoHeight;  // one quantity: the road points' road level follows it (next run)
  sliderD("ego height (m)", egoHeight, 0.0, 1.0);
  if (egoHeight != p.egoHeight) setEgoHeight(state.bench().config, egoHeight);
  sliderD("along-track sigma (m)", p.alongTrackSigma, 0.0, 5.0);
  ImGui::Text("robust loss and graph");
  sliderD("prior Huber (sigma)", g.priorHuber, 0.1, 10.0);
  ImGui::SliderInt("max iterations", &g.maxIterations, 1, 200);
  sliderD("odometry sigma per m", g.odometryTranslationSigmaPerM, 1e-5, 0.05, "%.5f");  // the schema's (0, 10]
  sliderD("odometry sigma (deg/m)", g.odometryRotationSigmaDegPerM, 1e-5, 0.1, "%.5f");
  const Session* session = state.bench().runner().session();
  ImGui::PopItemWidth();
  if (session != nullptr && !state.bench().runner().busy() && session->hasPriors() && state.bench().runner().lastSolve()) {
    const PoseGraphOptions& used = session->graphOptions();
    ImGui::TextWrapped("the solve's drift model, learnt from the priors: %.2g m/m, %.2g deg/m",
                       used.odometryTranslationSigmaPerM, used.odometryRotationSigmaDegPerM);
  }
}

void drawSummary(AppState& state) {
  const SessionRunner& runner = state.bench().runner();
  if (runner.lastSolve()) {
    const SolveSummary& s = *runner.lastSolve();
    ImGui::Text("last solve: %d iterations, %.1f ms, %s", s.iterations, runner.lastSolveMs(),
                s.converged ? "converged" : "not converged");
    ImGui::Text("cost %.4g -> %.4g", s.initialCost, s.finalCost);
  }
  const render::Analysis& a = state.bench().analysis();
  ImGui::Text("ATE rmse: before (odometry) %.3f m", finiteRmse(a.odometryError));
  ImGui::Text("          after (optimised) %.3f m", finiteRmse(a.optimizedError));
}

}  // namespace

void drawPgoTab(AppState& state) {
  TuningBench& bench = state.bench();
  const bool ready = bench.runner().session() != nullptr && bench.keyframeCount() > 0;
  ImGui::BeginDisabled(!ready);
  if (ImGui::Button("Optimise now")) bench.optimize();
  ImGui::EndDisabled();
  if (!ready) ImGui::TextDisabled(bench.runner().busy() ? "a job is running" : "run or step the pipeline first");
  drawSummary(state);
  ImGui::Separator();
  drawWeights(state);
}

}  // namespace hdprior::ui
