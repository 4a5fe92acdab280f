// Road paint as the map check's paint reading sees it in a log (sweeps at their logged poses):
// within ChangeOptions::laneRange of the sensor, which road returns pass its brightness threshold
// on the map's painted lane lines and away from all paint, and where its paint runs lie. The
// figures the simulator's road surface is drawn around (docs/simulator.md).
#pragma once
#include <algorithm>
#include <filesystem>
#include <vector>

#include "engine/changes/change_options.h"
#include "engine/changes/sweep_paint.h"
#include "engine/geom/polygon2d.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/vector_map.h"
#include "engine/pipeline/config.h"

namespace hdprior::test {

struct PaintStatistics {
  size_t sweeps = 0;
  long onLine = 0, onLineBright = 0;  // road returns within 0.15 m of a painted lane line
  long asphalt = 0, asphaltBright = 0;  // more than 1 m from every line, outside the crossings
  long runsOnLines = 0, runsElsewhere = 0;  // runs within 0.5 m of a line; runs off the lines and crossings
  std::vector<std::vector<Eigen::Vector2d>> elsewhere;  // per sweep, where those runs lie (city frame)
  double onLineBrightShare() const { return double(onLineBright) / double(std::max(1L, onLine)); }
  double asphaltBrightShare() const { return double(asphaltBright) / double(std::max(1L, asphalt)); }
  double runsOnLinesPerSweep() const { return double(runsOnLines) / double(std::max<size_t>(1, sweeps)); }
  double runsElsewherePerSweep() const { return double(runsElsewhere) / double(std::max<size_t>(1, sweeps)); }
};

// The painted lane lines (outside intersections) and crossings within `radius` of `centre`.
inline VectorMap paintedNear(const VectorMap& map, const Eigen::Vector2d& centre, double radius) {
  VectorMap near;
  for (const LaneSegment& l : map.laneSegments)
    if (!l.isIntersection && !l.leftLaneBoundary.empty() && (l.leftLaneBoundary[0].head<2>() - centre).norm() < radius)
      near.laneSegments.push_back(l);
  for (const PedestrianCrossing& c : map.pedestrianCrossings)
    if (!c.edge1.empty() && (c.edge1[0].head<2>() - centre).norm() < radius) near.pedestrianCrossings.push_back(c);
  return near;
}

inline double paintedLineDistance(const Eigen::Vector2d& p, const VectorMap& map) {
  double best = 1e9;
  for (const LaneSegment& l : map.laneSegments)
    for (bool left : {true, false}) {
      const Polyline3& line = left ? l.leftLaneBoundary : l.rightLaneBoundary;
      if (!isPaintedMark(left ? l.leftLaneMarkType : l.rightLaneMarkType)) continue;
      for (size_t i = 0; i + 1 < line.size(); ++i) best = std::min(best, segmentDistance(p, p, line[i].head<2>(), line[i + 1].head<2>()));
    }
  return best;
}

inline bool inCrossing(const Eigen::Vector2d& p, const VectorMap& map) {
  for (const PedestrianCrossing& c : map.pedestrianCrossings)
    if (ringContains(crossingOutline(c), p)) return true;
  return false;
}

// Every `every`-th sweep of the log, at most `maxSweeps`.
inline PaintStatistics paintStatistics(const std::filesystem::path& dir, size_t every, size_t maxSweeps) {
  const ArgoverseLog log(dir);
  const ChangeOptions options;
  const VectorMap map = paintedNear(readVectorMap(log.mapFiles().vectorMap), log.cityTEgo().poses().front().translation().head<2>(), 500.0);
  PaintStatistics s;
  for (size_t i = 0; i < log.sweepCount() && s.sweeps < maxSweeps; i += every) {
    const auto sweep = log.sweep(i);
    const SE3 pose = log.cityTEgo().at(sweep->timestampNs);
    const LabelledSweep labelled = labelSweep(*sweep, levelRotation(pose), defaultConfig().roadPoints);
    const Eigen::Rotation2Dd yaw(yawOf(pose));
    const Eigen::Vector2d origin = pose.translation().head<2>();
    std::vector<uint8_t> near;
    for (size_t k = 0; k < labelled.points.size(); ++k)
      if (labelled.road[k] && labelled.points[k].head<2>().norm() <= options.laneRange) near.push_back(sweep->points[k].intensity);
    if (near.empty()) continue;
    ++s.sweeps;
    s.elsewhere.emplace_back();
    std::nth_element(near.begin(), near.begin() + long(near.size() / 2), near.end());
    const double threshold = options.paintContrast * near[near.size() / 2];
    for (size_t k = 0; k < labelled.points.size(); ++k) {
      if (!labelled.road[k] || labelled.points[k].head<2>().norm() > options.laneRange) continue;
      const Eigen::Vector2d city = yaw * labelled.points[k].head<2>() + origin;
      if (inCrossing(city, map)) continue;
      const bool bright = sweep->points[k].intensity > threshold;
      const double d = paintedLineDistance(city, map);
      if (d < 0.15) ++s.onLine, s.onLineBright += bright;
      else if (d > 1.0) ++s.asphalt, s.asphaltBright += bright;
    }
    for (const PaintRun& r : findSweepPaint(*sweep, labelled, options).runs) {
      if (r.centre.norm() > options.laneRange) continue;
      const Eigen::Vector2d city = yaw * r.centre + origin;
      if (paintedLineDistance(city, map) < 0.5) ++s.runsOnLines;
      else if (!inCrossing(city, map)) ++s.runsElsewhere, s.elsewhere.back().push_back(city);
    }
  }
  return s;
}

}  // namespace hdprior::test
