#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "engine/pipeline/keyframe_diagnostics.h"

namespace hdprior {

struct SkippedSweep;

// A place in a run worth looking at, for the bench to jump to.
struct RunEvent {
  enum class Kind { Rejected, Gated, ConstraintChange, Beyond3Sigma, SkippedSweep, MapChange, MissedChange, MisalignedSweeps };
  Kind kind = Kind::Rejected;
  // frame: the log's sweep index; a skipped sweep's keyframe is the one before it; a map change's
  // frame is the sweep that saw it best (a missed labelled change's: the sweep nearest to it), its
  // keyframe 0 (it belongs to no keyframe)
  size_t keyframe = 0, frame = 0;
  std::string detail;              // the reason, "lateral + yaw -> full", "lateral 0.52 m > 3 x 0.12 m", the problem
};

// Whether the event is a place in the log (the bench goes to its frame) rather than a keyframe's
// match (the bench inspects the keyframe).
inline bool isFrameEvent(RunEvent::Kind kind) {
  return kind == RunEvent::Kind::SkippedSweep || kind == RunEvent::Kind::MapChange || kind == RunEvent::Kind::MissedChange ||
         kind == RunEvent::Kind::MisalignedSweeps;
}
// Whether the event comes from a map check (and goes when the check is run again).
inline bool isMapCheckEvent(RunEvent::Kind kind) {
  return kind == RunEvent::Kind::MapChange || kind == RunEvent::Kind::MissedChange || kind == RunEvent::Kind::MisalignedSweeps;
}

// "rejected", "gated", "constraint-change", "beyond-3-sigma", "skipped-sweep", "map-change", "missed-change",
// "misaligned-sweeps".
const char* toString(RunEvent::Kind kind);

// A run's events in frame order: rejected and gated priors, a change in what consecutive priors fix,
// a prior's error beyond 3 of its sigmas (where the truth is known), and skipped sweeps.
std::vector<RunEvent> runEvents(const std::vector<KeyframeDiagnostic>& keyframes, const std::vector<SkippedSweep>& skipped);

// "event I keyframe K frame F KIND DETAIL", the script command `events`'s line.
std::string eventLine(size_t index, const RunEvent& event);

}  // namespace hdprior
