#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/match/match_result.h"

namespace hdprior {

// The labels of a keyframe sweep's points (pointLabels).
enum class SubmapLabel : uint8_t { Other = 0, Ground = 1, Road = 2, Curb = 3 };

// What the tuning bench shows of one keyframe, re-computed on demand with the options being tuned:
// its sweep (the one the road points come from) labelled other / ground / road / curb in the
// keyframe's level frame (x forward, y left, z up from the ego origin, roll and pitch removed), the
// road points the matcher saw, and the match from `start` with every iterate.
struct KeyframeInspection {
  size_t keyframe = 0, frame = 0;  // frame: the log's sweep index of the keyframe
  int64_t timestampNs = 0;
  SE3 keyframePose = SE3::Identity();  // city_T_ego the run has for it (optimised when a graph exists)
  std::optional<Eigen::Vector3d> truth;  // ground-truth (x, y, yaw), when the log's poses cover it
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // the match's start (x, y, yaw)
  std::vector<Eigen::Vector3f> points;  // the sweep, level frame
  std::vector<SubmapLabel> labels;       // one per point
  std::vector<Eigen::Vector2d> roadPoints, curbPoints;  // what the matcher got (thinned road, curbs)
  MatchResult match;
};

}  // namespace hdprior
