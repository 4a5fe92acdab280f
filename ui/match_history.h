#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/pipeline/config.h"
#include "engine/pipeline/keyframe_inspection.h"

namespace hdprior::ui {

// One re-match of the NDT tab: the parameters it ran with (and what changed since the row
// before), and what came out.
struct MatchHistoryRow {
  Config config;
  Eigen::Vector3d startOffset = Eigen::Vector3d::Zero();
  size_t keyframe = 0;
  std::vector<std::string> changes;  // configDifferences from the row before, plus the keyframe and offset
  std::string constraint;            // what the match fixes, or why it was rejected
  double score = 0.0;
  std::optional<Eigen::Vector3d> error;  // along, lateral (m), yaw (rad) against the truth
};

// Every re-match, newest last; a user restores any row's parameters from it.
class MatchHistory {
 public:
  void add(const Config& config, const Eigen::Vector3d& startOffset, const KeyframeInspection& inspection);
  const std::vector<MatchHistoryRow>& rows() const { return rows_; }
  void clear() { rows_.clear(); }

 private:
  std::vector<MatchHistoryRow> rows_;
};

}  // namespace hdprior::ui
