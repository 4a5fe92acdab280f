#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/changes/map_verdict.h"
#include "engine/changes/sweep_paint.h"
#include "engine/geom/se3.h"
#include "engine/io/vector_map.h"

namespace hdprior {

// A stretch (options.stretchLength) of a painted lane boundary of the map, judged by the paint
// runs the lidar saw beside it within options.laneRange of the sensor.
struct LaneLineStretch {
  int64_t laneId = 0;  // the lane segment whose boundary it is (the first, when two lanes share it)
  std::string side;    // "left" or "right" of that lane
  std::string markType;
  int index = 0;  // along the boundary from its first vertex
  std::vector<Eigen::Vector2d> line;
  MapVerdict verdict = MapVerdict::Unobserved;
  double confidence = 0.0;
  double offset = 0.0;  // contradicted: where the paint is, metres to the left of the line (negative: right)
  int runsOnLine = 0;   // paint runs within 0.5 m of the line
  int runsAtOffset = 0;  // contradicted: the runs around `offset`
  int firstFrame = -1, bestFrame = -1;  // the first frame with a run beside it; the one with most
};

// The paint beside the map's painted lane lines. A stretch with runs on its line is consistent;
// one with none on it and options.laneOffsetRuns or more within half a metre of one place 0.75-1.5 m
// beside it is contradicted (the paint is where the line is not); the rest are unobserved. Runs
// in or beside a crossing are the crossing's. Worn or dashed paint never contradicts a line alone,
// and a sweep whose runs lie beside the lines more than on them is left out as off its pose, when
// they lie beside two lines or more, or no run is on a line (a restriping moves one line; a pose
// error moves every line in view).
class LaneLineEvidence {
 public:
  LaneLineEvidence(const VectorMap& map, const ChangeOptions& options);

  // A sweep's paint (findSweepPaint) at city_T_ego.
  void add(int frame, const SweepPaint& paint, const SE3& cityTEgo);

  std::vector<LaneLineStretch> stretches() const;  // those with a run beside them, judged
  // Sweeps left out: more of their runs beside the lines than on them (the pose is off, not the map).
  int misalignedFrames() const { return misalignedFrames_; }

 private:
  static constexpr int kBins = 12;  // of 0.25 m, offsets -1.5 .. 1.5 m
  struct Stretch {
    LaneLineStretch judged;
    std::array<int, kBins> runs{};
    std::array<int, kBins> bestFrameRuns{};
    int frameRuns = 0, bestRuns = 0, lastFrame = -1;
  };
  // The stretch a run at `city` is nearest to (within 1.5 m, outside every crossing) and its offset.
  std::optional<std::pair<size_t, double>> nearestStretch(const Eigen::Vector2d& city) const;
  void addRun(int frame, Stretch& stretch, double offset);

  ChangeOptions options_;
  std::vector<Stretch> stretches_;
  std::unordered_map<int64_t, std::vector<size_t>> cells_;  // 5 m cells -> the stretches passing near them
  std::vector<std::vector<Eigen::Vector2d>> crossings_;    // grown by a metre
  int misalignedFrames_ = 0;
};

}  // namespace hdprior
