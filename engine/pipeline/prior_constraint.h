#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

struct KeyframeMatch;
struct MatchResult;

// What a keyframe's match or prior tells the pose graph: the directions of the vehicle frame it
// fixes (along the heading, lateral, yaw), or why it tells nothing: the matcher rejected it, or the
// innovation gate left it out against the graph's prediction. On a straight road a prior that fixes
// lateral and yaw but not the along-track place is the normal, useful case.
struct PriorConstraint {
  enum class Kind { Fixes, Rejected, Gated };
  Kind kind = Kind::Rejected;
  bool along = false, lateral = false, yaw = false;
  std::string reason;  // Rejected: the matcher's reason; Gated: "chi2 X > Q" or "outside the prediction: chi2 X"

  bool full() const { return kind == Kind::Fixes && along && lateral && yaw; }
  // "full", "lateral + yaw", "lateral", "yaw", "along + lateral", ...; "rejected"; "gated".
  std::string category() const;
  // The category with its reason: "rejected: inlier ratio 0.61 < 0.85", "gated: chi2 14.2 > 11.3".
  std::string label() const;
  bool operator==(const PriorConstraint& o) const = default;
};

// The directions `information` (over city x, y, yaw, possibly singular) fixes in the frame of
// `estimate`'s heading, as matchErrorSample decides a direction observable.
PriorConstraint fixedDirections(const Eigen::Matrix3d& information, const Eigen::Vector3d& estimate);
// A match as the matcher judged it (no gate).
PriorConstraint constraintOf(const MatchResult& match);
// A keyframe as the graph took it: its prior's directions, or rejected, or gated.
PriorConstraint constraintOf(const KeyframeMatch& keyframe);

// Each keyframe's constraint.
std::vector<PriorConstraint> constraintsOf(const std::vector<KeyframeMatch>& keyframes);

// The categories in the order a summary lists them: full first, then partial, gated, rejected.
const std::vector<std::string>& constraintCategories();
// Counts per category, in constraintCategories() order, zero counts left out.
std::vector<std::pair<std::string, size_t>> countConstraints(const std::vector<PriorConstraint>& constraints);
// "26 full, 51 lateral + yaw, 12 rejected" ("none" when empty).
std::string constraintSummary(const std::vector<PriorConstraint>& constraints);

}  // namespace hdprior
