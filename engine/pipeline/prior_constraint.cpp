#include "engine/pipeline/prior_constraint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/eval/match_calibration.h"
#include "engine/geom/se2.h"
#include "engine/graph/pose_prior.h"
#include "engine/match/match_result.h"
#include "engine/pipeline/prior_stage.h"

namespace hdprior {

std::string PriorConstraint::category() const {
  if (kind == Kind::Rejected) return "rejected";
  if (kind == Kind::Gated) return "gated";
  if (full()) return "full";
  std::string s;
  for (const auto& [fixed, name] : {std::pair{along, "along"}, std::pair{lateral, "lateral"}, std::pair{yaw, "yaw"}})
    if (fixed) s += (s.empty() ? "" : " + ") + std::string(name);
  return s.empty() ? "nothing" : s;
}

std::string PriorConstraint::label() const {
  return reason.empty() || kind == Kind::Fixes ? category() : category() + ": " + reason;
}

PriorConstraint fixedDirections(const Eigen::Matrix3d& information, const Eigen::Vector3d& estimate) {
  const Eigen::Vector3d sigma = matchErrorSample(estimate, estimate, information).sigma;
  PriorConstraint c;
  c.kind = PriorConstraint::Kind::Fixes;
  c.along = std::isfinite(sigma(0));
  c.lateral = std::isfinite(sigma(1));
  c.yaw = std::isfinite(sigma(2));
  return c;
}

PriorConstraint constraintOf(const MatchResult& match) {
  if (match.status == MatchStatus::Rejected) return {.kind = PriorConstraint::Kind::Rejected, .reason = match.reason};
  return fixedDirections(match.information, match.estimate);
}

PriorConstraint constraintOf(const KeyframeMatch& k) {
  if (k.gated) {
    char reason[128];
    if (k.beyondOdometryReach) {
      std::snprintf(reason, sizeof reason, "chi2 %.1f > %.1f, its run beyond the odometry's reach", k.innovationChi2, k.gateQuantile);
    } else if (k.outsidePrediction) {
      std::snprintf(reason, sizeof reason, "outside the prediction: chi2 %.1f", k.match.gateChi2);
    } else {
      std::snprintf(reason, sizeof reason, "chi2 %.1f > %.1f", k.innovationChi2, k.gateQuantile);
    }
    PriorConstraint c = constraintOf(k.match);
    c.kind = PriorConstraint::Kind::Gated;
    c.reason = reason;
    return c;
  }
  if (!k.hasPrior) return constraintOf(k.match);
  return fixedDirections(marginalPlanarInformation(k.prior), planarPose(k.prior.pose));
}

std::vector<PriorConstraint> constraintsOf(const std::vector<KeyframeMatch>& keyframes) {
  std::vector<PriorConstraint> out;
  out.reserve(keyframes.size());
  for (const KeyframeMatch& k : keyframes) out.push_back(constraintOf(k));
  return out;
}

const std::vector<std::string>& constraintCategories() {
  static const std::vector<std::string> order = {"full",         "along + lateral", "along + yaw", "lateral + yaw", "along",
                                                 "lateral",      "yaw",             "nothing",     "gated",         "rejected"};
  return order;
}

std::vector<std::pair<std::string, size_t>> countConstraints(const std::vector<PriorConstraint>& constraints) {
  std::vector<std::pair<std::string, size_t>> counts;
  for (const std::string& category : constraintCategories()) {
    const size_t n = size_t(std::count_if(constraints.begin(), constraints.end(),
                                          [&](const PriorConstraint& c) { return c.category() == category; }));
    if (n > 0) counts.emplace_back(category, n);
  }
  return counts;
}

std::string constraintSummary(const std::vector<PriorConstraint>& constraints) {
  std::string s;
  for (const auto& [category, n] : countConstraints(constraints))
    s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + category;
  return s.empty() ? "none" : s;
}

}  // namespace hdprior
