#include "engine/map/hd_map.h"

#include <algorithm>
#include <cmath>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"

namespace hdprior {

HdMap HdMap::load(const LogMapFiles& files, const HdMapOptions& options) {
  VectorMap map = readVectorMap(files.vectorMap);
  GroundHeight height = options.groundHeightGeoTiff.empty()
                            ? readGroundHeight(files.groundHeight, files.sim2)
                            : readGroundHeightGeoTiff(options.groundHeightGeoTiff);
  return build(std::move(map), std::move(height), options, files.vectorMap.string());
}

HdMap HdMap::build(VectorMap map, std::optional<GroundHeight> groundHeight, const HdMapOptions& options,
                   const std::string& source) {
  HdMap hd;
  hd.drivable_ = DrivableRaster::build(map, options.raster, source);
  std::vector<double> sizes = options.ndtCellSizes;
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  for (double size : sizes) {
    NdtGridOptions ndt = options.ndt;
    ndt.cellSize = size;
    hd.ndtGrids_.push_back(NdtGrid::build(hd.drivable_, ndt));
  }
  if (options.boundaryDistance) hd.boundaryDistance_ = BoundaryDistance::build(hd.drivable_);
  hd.laneGraph_ = LaneGraph(map, options.lanes, source);
  hd.groundHeight_ = std::move(groundHeight);
  hd.vectorMap_ = std::move(map);
  return hd;
}

const NdtGrid& HdMap::ndtGrid(double cellSize) const {
  for (const NdtGrid& g : ndtGrids_) {
    if (std::abs(g.cellSize() - cellSize) <= 1e-9 * cellSize) return g;
  }
  throw Error("HD map", "no NDT grid with " + std::to_string(cellSize) + " m cells was built");
}

const BoundaryDistance& HdMap::boundaryDistance() const {
  if (!boundaryDistance_) throw Error("HD map", "the boundary distance field was not built");
  return *boundaryDistance_;
}

const GroundHeight& HdMap::groundHeight() const {
  if (!groundHeight_) throw Error("HD map", "the map has no ground-height raster");
  return *groundHeight_;
}

}  // namespace hdprior
