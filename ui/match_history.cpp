#include "ui/match_history.h"

#include <cstdio>

#include "engine/geom/se2.h"
#include "engine/pipeline/config_difference.h"
#include "engine/pipeline/prior_constraint.h"

namespace hdprior::ui {
namespace {

std::string offsetText(const Eigen::Vector3d& o) {
  char b[96];
  std::snprintf(b, sizeof b, "(%.2f, %.2f, %.1f deg)", o.x(), o.y(), o.z() * 180.0 / M_PI);
  return b;
}

std::vector<std::string> changesSince(const MatchHistoryRow* previous, const Config& config, const Eigen::Vector3d& offset,
                                      size_t keyframe) {
  if (!previous) return {"first match"};
  std::vector<std::string> changes;
  if (previous->keyframe != keyframe)
    changes.push_back("keyframe " + std::to_string(previous->keyframe) + " -> " + std::to_string(keyframe));
  if (previous->startOffset != offset) changes.push_back("start offset " + offsetText(previous->startOffset) + " -> " + offsetText(offset));
  for (std::string& d : configDifferences(previous->config, config)) changes.push_back(std::move(d));
  if (changes.empty()) changes.push_back("no change");
  return changes;
}

}  // namespace

void MatchHistory::add(const Config& config, const Eigen::Vector3d& startOffset, const KeyframeInspection& inspection) {
  MatchHistoryRow row;
  row.changes = changesSince(rows_.empty() ? nullptr : &rows_.back(), config, startOffset, inspection.keyframe);
  row.config = config;
  row.startOffset = startOffset;
  row.keyframe = inspection.keyframe;
  row.constraint = constraintOf(inspection.match).label();
  row.score = inspection.match.score;
  if (inspection.truth) row.error = planarError(*inspection.truth, inspection.match.estimate);
  rows_.push_back(std::move(row));
}

}  // namespace hdprior::ui
