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
#include "engine/pipeline/prior_constraint.h"
#include "render/constraint_palette.h"
#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

ImVec4 constraintColor(render::ConstraintClass c) {
  const Eigen::Vector4f v = render::constraintColour(c);
  return ImVec4(v.x(), v.y(), v.z(), v.w());
}

// The colours of the status legend, the list and the plots' markers (render/constraint_palette.h).
void drawLegend() {
  for (size_t c = 0; c < render::kConstraintClasses; ++c) {
    if (c > 0) ImGui::SameLine();
    ImGui::TextColored(constraintColor(render::ConstraintClass(c)), "%s", c == 1 ? "partial" : render::kConstraintClassNames[c]);
  }
}

void drawKeyframeList(AppState& state, const Session& session) {
  const auto& matches = session.matches();
  const auto& keyframes = session.odometry().keyframes();
  ImGui::TextWrapped("priors: %s", constraintSummary(constraintsOf(matches)).c_str());
  drawLegend();
  ImGui::BeginChild("keyframes", ImVec2(0, 150), true);
  for (size_t k = 0; k < keyframes.size(); ++k) {
    std::optional<PriorConstraint> c;
    if (k < matches.size()) c = constraintOf(matches[k]);
    const std::string label = std::to_string(k) + "  frame " + std::to_string(session.sweepOfFrame(keyframes[k].frame)) + "  " +
                              (c ? c->label() : "no match");
    ImGui::PushStyleColor(ImGuiCol_Text, constraintColor(render::constraintClass(c)));
    if (ImGui::Selectable(label.c_str(), state.bench().selected() == k)) state.inspectKeyframe(k);
    ImGui::PopStyleColor();
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
  const PriorConstraint constraint = constraintOf(r);
  ImGui::PushStyleColor(ImGuiCol_Text, constraintColor(render::constraintClass(constraint)));
  ImGui::TextWrapped("constrains: %s", constraint.label().c_str());
  ImGui::PopStyleColor();
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

// Run B's match of the same keyframe, when comparing.
void drawComparisonMatch(const render::Analysis& a) {
  if (!a.comparison || !a.comparison->inspection) return;
  const KeyframeInspection& b = *a.comparison->inspection;
  ImGui::Separator();
  const PriorConstraint c = constraintOf(b.match);
  ImGui::Text("B (%s), its keyframe %zu:", a.comparison->name.c_str(), b.keyframe);
  ImGui::PushStyleColor(ImGuiCol_Text, constraintColor(render::constraintClass(c)));
  ImGui::TextWrapped("  constrains: %s", c.label().c_str());
  ImGui::PopStyleColor();
  ImGui::Text("  score %.1f, inliers %.2f, %zu road points", b.match.score, b.match.inlierRatio, b.roadPoints.size());
  if (b.truth) {
    const Eigen::Vector3d e = planarError(*b.truth, b.match.estimate);
    ImGui::Text("  error: along %.3f, lateral %.3f m, yaw %.2f deg", e.x(), e.y(), e.z() * kDeg);
  }
}

void drawPriorResidual(const Session& session, size_t k) {
  if (k >= session.matches().size() || !session.graph()) return;
  const KeyframeMatch& m = session.matches()[k];
  const PriorConstraint c = constraintOf(m);
  ImGui::PushStyleColor(ImGuiCol_Text, constraintColor(render::constraintClass(c)));
  ImGui::TextWrapped("the run's prior: %s", c.label().c_str());
  ImGui::PopStyleColor();
  if (!m.hasPrior) return;
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
  if (inspection->truth && ImGui::SmallButton("measure estimate -> truth")) state.measureMatchError();
  drawComparisonMatch(state.bench().analysis());
  ImGui::Separator();
  drawPriorResidual(*session, inspection->keyframe);
}

}  // namespace hdprior::ui
