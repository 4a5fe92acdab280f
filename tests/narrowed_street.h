// A simulated log's map with the street the drive starts on drawn narrower than it is: the
// drivable area under the first pose loses `metres` on the side to the vehicle's left (its
// vertices more than 1 m left of the vehicle move towards it). A stale map for the change check.
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

// Returns the narrowed drivable area's id.
inline int64_t narrowStreetAtStart(const std::filesystem::path& log, double metres) {
  const ArgoverseLog opened(log);
  const std::filesystem::path file = opened.mapFiles().vectorMap;
  VectorMap map = readVectorMap(file);
  const SE3 first = opened.cityTEgoAtSweeps().poses().front();
  const Eigen::Vector2d ego = first.translation().head<2>(), left = first.linear().col(1).head<2>().normalized();
  auto area = std::find_if(map.drivableAreas.begin(), map.drivableAreas.end(),
                           [&](const DrivableArea& a) { return ringContains(ringOf(a.areaBoundary), ego); });
  if (area == map.drivableAreas.end()) throw Error(log.string(), "no drivable area under the first pose");
  for (Eigen::Vector3d& v : area->areaBoundary)
    if ((v.head<2>() - ego).dot(left) > 1.0) v.head<2>() -= metres * left;
  writeFileAtomically(file, vectorMapToJson(map));
  return area->id;
}

}  // namespace hdprior::test
