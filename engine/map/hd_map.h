#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/vector_map.h"
#include "engine/map/boundary_distance.h"
#include "engine/map/drivable_raster.h"
#include "engine/map/ground_height.h"
#include "engine/map/lane_graph.h"
#include "engine/map/ndt_grid.h"

namespace hdprior {

struct LogMapFiles;

struct HdMapOptions {
  DrivableRasterOptions raster;
  // One NDT grid per cell size, for coarse-to-fine matching; each a whole multiple of the
  // raster resolution. minPoints and minEigenRatio come from `ndt`.
  std::vector<double> ndtCellSizes = {1.0};
  NdtGridOptions ndt;
  bool boundaryDistance = true;
  LaneGraphOptions lanes;
  // When set, the ground height comes from this GeoTIFF instead of the log's .npy + Sim2.
  std::filesystem::path groundHeightGeoTiff;
};

// The HD-map of a log as the engine uses it: the vector map, the drivable raster with its
// NDT grids and boundary distance field, the ground surface height and the lane graph.
class HdMap {
 public:
  // Reads the log's map files; throws Error naming the file that is wrong.
  static HdMap load(const LogMapFiles& files, const HdMapOptions& options = {});
  // From a vector map in memory (synthetic maps); `source` names it in errors.
  static HdMap build(VectorMap map, std::optional<GroundHeight> groundHeight, const HdMapOptions& options,
                     const std::string& source);

  const VectorMap& vectorMap() const { return vectorMap_; }
  const DrivableRaster& drivable() const { return drivable_; }
  // Coarse to fine, in the order of options.ndtCellSizes sorted by decreasing size.
  const std::vector<NdtGrid>& ndtGrids() const { return ndtGrids_; }
  // The grid with this cell size; throws Error if there is none.
  const NdtGrid& ndtGrid(double cellSize) const;
  bool hasBoundaryDistance() const { return boundaryDistance_.has_value(); }
  const BoundaryDistance& boundaryDistance() const;  // throws Error if not built
  bool hasGroundHeight() const { return groundHeight_.has_value(); }
  const GroundHeight& groundHeight() const;  // throws Error if the map has none
  const LaneGraph& laneGraph() const { return laneGraph_; }

 private:
  VectorMap vectorMap_;
  DrivableRaster drivable_;
  std::vector<NdtGrid> ndtGrids_;
  std::optional<BoundaryDistance> boundaryDistance_;
  std::optional<GroundHeight> groundHeight_;
  LaneGraph laneGraph_;
};

}  // namespace hdprior
