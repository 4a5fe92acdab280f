#pragma once
// Keyframe diagnostics made up for tests and benchmarks of `hdprior plot`: every status, gaps where a
// direction is not fixed, a gate line, and the keyframes.json text readKeyframeDiagnostics reads.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "engine/pipeline/keyframe_diagnostics.h"

namespace hdprior::test {

// Keyframe k at frame 3k + 1: mostly lateral + yaw, full every 7th, gated every 11th, rejected every
// 13th (no sigma, chi2, residual or prior error then); values follow slow waves shifted by `phase`.
inline std::vector<KeyframeDiagnostic> syntheticDiagnostics(size_t keyframes, double phase = 0.0) {
  using F = DiagnosticField;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<KeyframeDiagnostic> rows(keyframes);
  for (size_t k = 0; k < keyframes; ++k) {
    KeyframeDiagnostic& d = rows[k];
    const double t = double(k) * 0.15 + phase;
    d.keyframe = k;
    d.frame = 3 * k + 1;
    const bool rejected = k % 13 == 5, gated = !rejected && k % 11 == 3, full = k % 7 == 0;
    d.constraint.kind = rejected ? PriorConstraint::Kind::Rejected : gated ? PriorConstraint::Kind::Gated : PriorConstraint::Kind::Fixes;
    d.constraint.along = !rejected && full;
    d.constraint.lateral = d.constraint.yaw = !rejected;
    d.constraint.reason = rejected ? "inlier ratio 0.61 < 0.85" : gated ? "chi2 14.2 > 11.3" : "";
    d[F::ScorePerPoint] = 0.55 + 0.2 * std::sin(t);
    d[F::InlierRatio] = rejected ? 0.61 : 0.9 + 0.05 * std::cos(t);
    d[F::RoadPoints] = std::round(3000 + 800 * std::sin(0.5 * t));
    d[F::CurbPoints] = std::round(300 + 150 * std::cos(0.7 * t));
    d[F::SigmaAlong] = d.constraint.along ? 0.3 + 0.1 * std::sin(t) : nan;
    d[F::SigmaLateral] = rejected ? nan : 0.05 + 0.02 * std::cos(t);
    d[F::SigmaYawDeg] = rejected ? nan : 0.2 + 0.05 * std::sin(2 * t);
    d[F::InnovationChi2] = rejected ? nan : gated ? 14.2 : 3.0 + 2.5 * std::sin(1.3 * t);
    d[F::GateQuantile] = rejected ? nan : 11.34;
    d[F::ResidualChi2] = rejected || gated ? nan : 1.0 + 0.8 * std::cos(0.9 * t);
    d[F::MatchErrorAlong] = 0.4 * std::sin(0.8 * t);
    d[F::MatchErrorLateral] = 0.06 * std::cos(1.1 * t);
    d[F::MatchErrorYawDeg] = 0.15 * std::sin(0.6 * t);
    d[F::PriorErrorAlong] = d.constraint.along && !gated ? 0.2 * std::sin(0.8 * t) : nan;
    d[F::PriorErrorLateral] = rejected || gated ? nan : 0.04 * std::cos(1.1 * t);
    d[F::PriorErrorYawDeg] = rejected || gated ? nan : 0.1 * std::sin(0.6 * t);
    d[F::AteAlong] = 0.1 * std::sin(0.2 * t);
    d[F::AteLateral] = -0.05 + 0.03 * std::cos(0.3 * t);
  }
  return rows;
}

inline std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// A keyframes.json holding what readKeyframeDiagnostics reads of each keyframe.
inline std::string keyframesJson(const std::vector<KeyframeDiagnostic>& rows) {
  std::string s = "[\n";
  for (size_t k = 0; k < rows.size(); ++k) {
    const KeyframeDiagnostic& d = rows[k];
    const PriorConstraint& c = d.constraint;
    const auto flag = [](bool b) { return b ? "true" : "false"; };
    s += " {\"index\": " + std::to_string(d.keyframe) + ", \"frame\": " + std::to_string(d.frame) +
         ", \"match\": {\"constrains\": \"" + c.label() + "\", \"constraint\": {\"category\": \"" + c.category() +
         "\", \"along\": " + flag(c.along) + ", \"lateral\": " + flag(c.lateral) + ", \"yaw\": " + flag(c.yaw) +
         "}}, \"diagnostics\": {";
    for (size_t f = 0; f < kDiagnosticFields; ++f)
      s += std::string(f ? ", " : "") + "\"" + diagnosticKey(DiagnosticField(f)) + "\": " + jsonNumber(d.values[f]);
    s += k + 1 < rows.size() ? "}},\n" : "}}\n";
  }
  return s + "]\n";
}

}  // namespace hdprior::test
