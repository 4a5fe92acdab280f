#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <Eigen/Eigenvalues>

#include "engine/eval/match_calibration.h"
#include "engine/geom/se2.h"
#include "engine/graph/pose_prior.h"
#include "engine/odom/odometry.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

ImVec4 statusColor(MatchStatus s) {
  switch (s) {
    case MatchStatus::Accepted: return ImVec4(0.35f, 0.85f, 0.35f, 1.0f);
    case MatchStatus::Degenerate: return ImVec4(1.0f, 0.75f, 0.2f, 1.0f);
    case MatchStatus::Rejected: return ImVec4(1.0f, 0.35f, 0.3f, 1.0f);
  }
  return ImVec4(1, 1, 1, 1);
}

void drawKeyframeList(AppState& state, const Session& session) {
  const auto& matches = session.matches();
  const auto& keyframes = session.odometry().keyframes();
  ImGui::BeginChild("keyframes", ImVec2(0, 150), true);
  for (size_t k = 0; k < keyframes.size(); ++k) {
    char label[96];
    const char* status = k < matches.size() ? toString(matches[k].match.status) : "no match";
    std::snprintf(label, sizeof label, "%3zu  frame %4zu  %s", k, session.sweepOfFrame(keyframes[k].frame), status);
    if (k < matches.size()) ImGui::PushStyleColor(ImGuiCol_Text, statusColor(matches[k].match.status));
    if (ImGui::Selectable(label, state.bench().selected() == k)) state.inspectKeyframe(k);
    if (k < matches.size()) ImGui::PopStyleColor();
  }
  ImGui::EndChild();
}

void drawSubmap(const KeyframeInspection& in) {
  size_t counts[4] = {0, 0, 0, 0};
  for (SubmapLabel l : in.labels) ++counts[int(l)];
  ImGui::Text("sub-map: %zu points", in.points.size());
  ImGui::Text("  road %zu, curb %zu, other ground %zu", counts[2], counts[3], counts[1]);
  ImGui::Text("  non-ground %zu", counts[0]);
  ImGui::Text("to the matcher: %zu road (thinned), %zu curb", in.roadPoints.size(), in.curbPoints.size());
}

std::string bounded(double v) {
  if (!std::isfinite(v)) return "free";
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}

void drawMatch(const KeyframeInspection& in) {
  const MatchResult& r = in.match;
  ImGui::TextColored(statusColor(r.status), "%s", toString(r.status));
  if (!r.reason.empty()) ImGui::TextWrapped("(%s)", r.reason.c_str());
  ImGui::Text("x %.2f  y %.2f  yaw %.2f deg", r.estimate.x(), r.estimate.y(), r.estimate.z() * kDeg);
  ImGui::Text("score %.1f, inliers %.2f", r.score, r.inlierRatio);
  ImGui::Text("%d iterations, %.1f ms", r.iterations, r.timeMs);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> covariance(r.covariance);
  const Eigen::Vector3d c = covariance.eigenvalues();
  ImGui::Text("covariance eigenvalues (x, y, yaw):");
  ImGui::Text("  %.2e  %.2e  %.2e", c(0), c(1), c(2));
  ImGui::Text("sigma x %.3f  y %.3f m  yaw %.3f deg", std::sqrt(r.covariance(0, 0)), std::sqrt(r.covariance(1, 1)),
              std::sqrt(r.covariance(2, 2)) * kDeg);
  // In the vehicle frame: what the prior claims and what the road points allow ("free": unobservable).
  const Eigen::Vector3d s = matchErrorSample(r.estimate, r.estimate, r.information).sigma;
  const Eigen::Vector3d& w = r.evidenceHalfWidths;
  ImGui::Text("sigma along %s  lat %s m  yaw %s deg", bounded(s.x()).c_str(), bounded(s.y()).c_str(),
              bounded(s.z() * kDeg).c_str());
  ImGui::Text("half-widths along %s  lat %s m  yaw %s deg", bounded(w.x()).c_str(), bounded(w.y()).c_str(),
              bounded(w.z() * kDeg).c_str());
  ImGui::Text("edge constraint eigenvalues %.0f %.0f %.0f", r.eigenvalues(0), r.eigenvalues(1), r.eigenvalues(2));
  ImGui::Text("observable directions: %d of 3", r.observableDirections);
  if (r.observableDirections < 3) ImGui::TextDisabled("  (no information, covariance 0, in the others)");
  if (in.truth) {
    const Eigen::Vector3d e = planarError(*in.truth, r.estimate);
    ImGui::Text("error vs truth: along %.3f m", e.x());
    ImGui::Text("  lateral %.3f m, yaw %.2f deg", e.y(), e.z() * kDeg);
  }
}

void drawPriorResidual(const Session& session, size_t k) {
  if (k >= session.matches().size() || !session.graph()) return;
  const KeyframeMatch& m = session.matches()[k];
  if (!m.hasPrior) {
    ImGui::TextWrapped("no prior in the graph (the run's match was rejected: %s)", m.match.reason.c_str());
    return;
  }
  const PriorResidual r = priorResidual(m.prior, session.graph()->pose(k));
  ImGui::Text("prior residual in the optimised graph:");
  ImGui::Text("  yaw %.2f deg, chi2 %.2f", r.error(0) * kDeg, r.chi2);
  ImGui::Text("  x %.3f  y %.3f  z %.3f m", r.error(1), r.error(2), r.error(3));
}

}  // namespace

void drawKeyframeTab(AppState& state) {
  const Session* session = state.bench().runner().session();
  if (!session || session->odometry().keyframes().empty()) {
    ImGui::TextDisabled("run or step the pipeline to have keyframes");
    return;
  }
  drawKeyframeList(state, *session);
  const auto& inspection = state.bench().inspection();
  if (!inspection) {
    ImGui::TextDisabled("select a keyframe");
    return;
  }
  ImGui::Text("keyframe %zu, frame %zu", inspection->keyframe, inspection->frame);
  ImGui::SameLine();
  if (ImGui::SmallButton("go to frame")) state.goToFrame((long long)inspection->frame);
  drawSubmap(*inspection);
  ImGui::Separator();
  ImGui::Text("match (tuned options):");
  drawMatch(*inspection);
  ImGui::Separator();
  drawPriorResidual(*session, inspection->keyframe);
}

}  // namespace hdprior::ui
