#pragma once
#include <array>
#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "engine/pipeline/prior_constraint.h"

namespace hdprior {

// How a keyframe is coloured wherever it is drawn (the keyframes layer, the bench's list and plots,
// `hdprior plot`'s markers): by what its prior fixes, or why it has none. The one source of these
// colours; render/constraint_palette.h passes them on to the renderer and the app.
enum class ConstraintClass { Full, Partial, Gated, Rejected, NoPrior };
inline constexpr size_t kConstraintClasses = 5;
inline constexpr std::array<const char*, kConstraintClasses> kConstraintClassNames = {
    "full", "partial (e.g. lateral + yaw)", "gated", "rejected", "no prior"};

inline ConstraintClass constraintClass(const std::optional<PriorConstraint>& c) {
  if (!c) return ConstraintClass::NoPrior;
  if (c->kind == PriorConstraint::Kind::Rejected) return ConstraintClass::Rejected;
  if (c->kind == PriorConstraint::Kind::Gated) return ConstraintClass::Gated;
  return c->full() ? ConstraintClass::Full : ConstraintClass::Partial;
}

// RGBA in 0..1: green, sky blue (the normal case on a straight road, not a warning), yellow, red, grey.
inline Eigen::Vector4f constraintColour(ConstraintClass c) {
  static const std::array<Eigen::Vector4f, kConstraintClasses> colours = {
      Eigen::Vector4f(0.20f, 0.85f, 0.30f, 1.0f), Eigen::Vector4f(0.30f, 0.65f, 1.00f, 1.0f),
      Eigen::Vector4f(1.00f, 0.85f, 0.15f, 1.0f), Eigen::Vector4f(0.95f, 0.20f, 0.20f, 1.0f),
      Eigen::Vector4f(0.60f, 0.60f, 0.60f, 1.0f)};
  return colours[size_t(c)];
}

}  // namespace hdprior
