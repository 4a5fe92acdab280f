#include "engine/pipeline/run_events.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "engine/pipeline/pipeline_run.h"

namespace hdprior {
namespace {

using F = DiagnosticField;

// The directions whose prior error is beyond 3 of the prior's sigmas; empty when none (or no truth).
std::string beyond3Sigma(const KeyframeDiagnostic& d) {
  struct Axis {
    const char* name;
    F error, sigma;
    const char* unit;
  };
  static constexpr Axis axes[] = {{"along", F::PriorErrorAlong, F::SigmaAlong, "m"},
                                  {"lateral", F::PriorErrorLateral, F::SigmaLateral, "m"},
                                  {"yaw", F::PriorErrorYawDeg, F::SigmaYawDeg, "deg"}};
  std::string out;
  for (const Axis& a : axes) {
    const double e = d[a.error], s = d[a.sigma];
    if (!(std::isfinite(e) && std::isfinite(s) && std::abs(e) > 3.0 * s)) continue;
    char b[96];
    std::snprintf(b, sizeof b, "%s%s %.3g %s > 3 x %.3g %s", out.empty() ? "" : ", ", a.name, std::abs(e), a.unit, s, a.unit);
    out += b;
  }
  return out;
}

bool usedPrior(const KeyframeDiagnostic& d) { return d.constraint.kind == PriorConstraint::Kind::Fixes; }

}  // namespace

const char* toString(RunEvent::Kind kind) {
  switch (kind) {
    case RunEvent::Kind::Rejected: return "rejected";
    case RunEvent::Kind::Gated: return "gated";
    case RunEvent::Kind::ConstraintChange: return "constraint-change";
    case RunEvent::Kind::Beyond3Sigma: return "beyond-3-sigma";
    case RunEvent::Kind::SkippedSweep: return "skipped-sweep";
    case RunEvent::Kind::MapChange: return "map-change";
    case RunEvent::Kind::MissedChange: return "missed-change";
    case RunEvent::Kind::MisalignedSweeps: return "misaligned-sweeps";
  }
  return "?";
}

std::vector<RunEvent> runEvents(const std::vector<KeyframeDiagnostic>& keyframes, const std::vector<SkippedSweep>& skipped) {
  std::vector<RunEvent> events;
  std::optional<std::string> previous;  // what the last used prior fixed
  for (const KeyframeDiagnostic& d : keyframes) {
    const PriorConstraint& c = d.constraint;
    if (c.kind == PriorConstraint::Kind::Rejected) events.push_back({RunEvent::Kind::Rejected, d.keyframe, d.frame, c.reason});
    if (c.kind == PriorConstraint::Kind::Gated) events.push_back({RunEvent::Kind::Gated, d.keyframe, d.frame, c.reason});
    if (!usedPrior(d)) continue;
    if (previous && *previous != c.category())
      events.push_back({RunEvent::Kind::ConstraintChange, d.keyframe, d.frame, *previous + " -> " + c.category()});
    previous = c.category();
    if (std::string far = beyond3Sigma(d); !far.empty())
      events.push_back({RunEvent::Kind::Beyond3Sigma, d.keyframe, d.frame, std::move(far)});
  }
  for (const SkippedSweep& s : skipped) {
    size_t keyframe = 0;
    for (const KeyframeDiagnostic& d : keyframes)
      if (d.frame <= s.index) keyframe = d.keyframe;
    events.push_back({RunEvent::Kind::SkippedSweep, keyframe, s.index, s.problem});
  }
  std::stable_sort(events.begin(), events.end(), [](const RunEvent& a, const RunEvent& b) { return a.frame < b.frame; });
  return events;
}

std::string eventLine(size_t index, const RunEvent& e) {
  return "event " + std::to_string(index) + " keyframe " + std::to_string(e.keyframe) + " frame " + std::to_string(e.frame) +
         " " + toString(e.kind) + " " + e.detail;
}

}  // namespace hdprior
