#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "engine/geom/pose_trajectory.h"
#include "engine/geom/se3.h"
#include "engine/pipeline/prior_constraint.h"

namespace hdprior {

struct KeyframeMatch;

// The evidence of one keyframe as the debugging bench plots it over the log. Values are in display
// units (metres, degrees); NaN where there is nothing to show: a direction the prior does not fix,
// no ground truth, no prior in the graph.
enum class DiagnosticField : uint8_t {
  ScorePerPoint, InlierRatio, RoadPoints, CurbPoints,
  SigmaAlong, SigmaLateral, SigmaYawDeg,                    // the prior's (a gated match's own); NaN: not fixed
  InnovationChi2, GateQuantile,                             // against the graph's prediction
  ResidualChi2,                                             // the prior at the optimised pose
  MatchErrorAlong, MatchErrorLateral, MatchErrorYawDeg,     // the match's estimate against the truth
  PriorErrorAlong, PriorErrorLateral, PriorErrorYawDeg,     // the prior's pose against the truth
  AteAlong, AteLateral,                                     // the keyframe's optimised pose against the truth
  Count
};
inline constexpr size_t kDiagnosticFields = size_t(DiagnosticField::Count);
// The field's key in keyframes.json's "diagnostics" ("score_per_point", "sigma_lateral_m", ...).
const char* diagnosticKey(DiagnosticField field);

struct KeyframeDiagnostic {
  size_t keyframe = 0, frame = 0;  // frame: the log's sweep index
  PriorConstraint constraint;
  std::array<double, kDiagnosticFields> values;
  KeyframeDiagnostic();
  double operator[](DiagnosticField f) const { return values[size_t(f)]; }
  double& operator[](DiagnosticField f) { return values[size_t(f)]; }
};

// Every keyframe's diagnostics: `matches` as the prior stage left them, `keyframePoses` the graph's
// optimised poses (city_T_ego, one per keyframe), `truth` the log's poses (empty: none),
// sweepOfFrame the log's sweep index of an odometry frame.
std::vector<KeyframeDiagnostic> keyframeDiagnostics(const std::vector<KeyframeMatch>& matches,
                                                    const std::vector<SE3>& keyframePoses, const PoseTrajectory& truth,
                                                    const std::function<size_t(size_t)>& sweepOfFrame);

// The diagnostics a run folder's keyframes.json holds (written with each keyframe's match); throws
// Error naming the file when it is missing, not JSON or lacks a keyframe's fields.
std::vector<KeyframeDiagnostic> readKeyframeDiagnostics(const std::filesystem::path& keyframesJson);

}  // namespace hdprior
