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
#include "engine/changes/paint_cells.h"
#include "engine/changes/sweep_paint.h"
#include "engine/geom/se3.h"
#include "engine/io/vector_map.h"

namespace hdprior {

// A stretch (options.stretchLength) of a painted lane boundary of the map, judged by the painted
// cells the lidar saw beside it within options.laneRange of the sensor.
struct LaneLineStretch {
  int64_t laneId = 0;  // the lane segment whose boundary it is (the first, when two lanes share it)
  std::string side;    // "left" or "right" of that lane
  std::string markType;
  int index = 0;  // along the boundary from its first vertex
  std::vector<Eigen::Vector2d> line;
  MapVerdict verdict = MapVerdict::Unobserved;
  double confidence = 0.0;
  // The verdict, its evidence and the frames are the whole line's (every stretch of it).
  double offset = 0.0;  // contradicted: where the paint is, metres to the left of the line (negative: right)
  PaintTally onLine;    // the road cells within a quarter metre of the line, and those painted
  PaintTally atOffset;  // contradicted: the half metre around `offset`
  double asphaltShare = 0.0;  // the log's painted share off the map's paint
  int firstFrame = -1, bestFrame = -1;  // the first frame with a run beside the line; the one with most
};

// The paint beside the map's painted lane lines, in the painted cells (PaintCells) of the drive
// within options.laneRange of the sensor, against the log's asphalt (its share of painted cells
// off the map's paint, from CrossingEvidence). Each line is judged whole, by the cells of all its
// stretches in 0.25 m bins of their offset to it, within 2 m of it and nearer to it than to any
// other line. It is consistent when its own half metre reads as painted (options.laneLineContrast
// times the asphalt's share, by options.laneLineEvidence), contradicted when it reads as asphalt
// (options.laneLineAsphalt) while a half metre 0.75 m or more beside it reads as painted: the
// paint is where the line is not. The rest are unobserved. Cells in or beside a crossing are the
// crossing's. A sweep whose paint runs lie beside the lines more than on them is left out as off
// its pose, when they lie beside two lines or more, or no run is on a line (a restriping moves one
// line; a pose error moves every line in view).
class LaneLineEvidence {
 public:
  LaneLineEvidence(const VectorMap& map, const ChangeOptions& options);

  // A sweep's paint (findSweepPaint) at city_T_ego.
  void add(int frame, const SweepPaint& paint, const SE3& cityTEgo);

  // Those with a road cell beside them, judged against the log's asphalt share (CrossingEvidence).
  std::vector<LaneLineStretch> stretches(double asphaltShare) const;
  // Sweeps left out: more of their runs beside the lines than on them (the pose is off, not the map).
  int misalignedFrames() const { return misalignedFrames_; }

 private:
  static constexpr int kBins = 16;  // of 0.25 m, offsets -2 .. 2 m
  struct Stretch {
    LaneLineStretch judged;
    int frameRuns = 0, bestRuns = 0, lastFrame = -1;
  };
  using Profile = std::array<PaintTally, kBins>;  // a stretch's cells by their offset to its line
  // The stretch a point is nearest to (within 2 m, outside every crossing) and its offset.
  std::optional<std::pair<size_t, double>> nearestStretch(const Eigen::Vector2d& city) const;
  void addRun(int frame, Stretch& stretch);
  std::vector<Profile> profiles() const;  // per stretch
  // A line's verdict from its stretches' profiles together, into each of its stretches.
  void judge(const Profile& line, double asphaltShare, LaneLineStretch& stretch) const;

  ChangeOptions options_;
  std::vector<Stretch> stretches_;
  std::unordered_map<int64_t, std::vector<size_t>> cells_;  // 5 m cells -> the stretches passing near them
  std::vector<std::vector<Eigen::Vector2d>> crossings_;    // grown by a metre
  PaintCells paint_;
  int misalignedFrames_ = 0;
};

}  // namespace hdprior
