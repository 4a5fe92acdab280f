#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/geom/se3.h"

namespace hdprior {

// Timestamped poses (e.g. city_T_ego), strictly increasing in time, interpolated at any
// timestamp inside their span.
class PoseTrajectory {
 public:
  PoseTrajectory() = default;
  // Throws Error(source, ...) if sizes differ or timestamps do not strictly increase.
  PoseTrajectory(std::vector<int64_t> timestampsNs, std::vector<SE3> poses, std::string source = "trajectory");

  size_t size() const { return timestamps_.size(); }
  bool empty() const { return timestamps_.empty(); }
  int64_t startNs() const { return timestamps_.front(); }
  int64_t endNs() const { return timestamps_.back(); }
  const std::vector<int64_t>& timestamps() const { return timestamps_; }
  const std::vector<SE3>& poses() const { return poses_; }

  bool covers(int64_t tNs) const { return !empty() && tNs >= startNs() && tNs <= endNs(); }
  // Throws Error naming the source and the span when tNs is outside it.
  SE3 at(int64_t tNs) const;

 private:
  std::vector<int64_t> timestamps_;
  std::vector<SE3> poses_;
  std::string source_;
};

}  // namespace hdprior
