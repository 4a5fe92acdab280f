// A simulated log's map with one lane line drawn where it is not painted: the painted lane boundary
// nearest to the first pose moved sideways (every lane's copy of it). A stale map for the lane-line
// check.
#pragma once
#include <algorithm>
#include <cstdint>
#include <filesystem>

#include "engine/error.h"
#include "engine/geom/polygon2d.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"

namespace hdprior::test {

// Moves it `metres` to its left (a constant shift: its direction at the point nearest to the first
// pose). Returns the line as the map now draws it.
inline Ring2 moveALaneLine(const std::filesystem::path& log, double metres) {
  const ArgoverseLog opened(log);
  const Eigen::Vector2d first = opened.cityTEgoAtSweeps().poses().front().translation().head<2>();
  VectorMap map = readVectorMap(opened.mapFiles().vectorMap);
  const Polyline3* nearest = nullptr;
  double best = 1e9;
  for (const LaneSegment& lane : map.laneSegments)
    for (const auto& [line, type] : {std::pair{&lane.leftLaneBoundary, &lane.leftLaneMarkType}, std::pair{&lane.rightLaneBoundary, &lane.rightLaneMarkType}}) {
      if (!isPaintedMark(*type) || line->size() < 2) continue;
      const Ring2 planar = ringOf(*line);
      const Eigen::Vector2d p[1] = {first};
      const double d = polylineDistance(p, planar, false);
      if (d < best) best = d, nearest = line;
    }
  if (!nearest || best > 6.0) throw Error(log.string(), "no painted lane line near the first pose");
  const Polyline3 original = *nearest;
  size_t segment = 0;
  for (size_t i = 0; i + 1 < original.size(); ++i) {
    const Eigen::Vector2d p[1] = {first}, s[2] = {original[i].head<2>(), original[i + 1].head<2>()};
    if (polylineDistance(p, s, false) <= best + 1e-9) segment = i;
  }
  const Eigen::Vector2d left = leftNormal(original[segment].head<2>(), original[segment + 1].head<2>());
  auto same = [&](const Polyline3& line) {
    return line == original || Polyline3(line.rbegin(), line.rend()) == original;
  };
  for (LaneSegment& lane : map.laneSegments)
    for (Polyline3* line : {&lane.leftLaneBoundary, &lane.rightLaneBoundary})
      if (same(*line))
        for (Eigen::Vector3d& v : *line) v.head<2>() += metres * left;
  writeFileAtomically(opened.mapFiles().vectorMap, vectorMapToJson(map));
  Ring2 moved;
  for (const Eigen::Vector3d& v : original) moved.push_back(v.head<2>() + metres * left);
  return moved;
}

}  // namespace hdprior::test
