#include <cstdio>

#include "app/command_line.h"
#include "app/commands.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/map/map_export.h"

namespace hdprior::app {

int runExportMap(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"out", "resolution"}, .flags = {}, .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior export-map LOG --out DIR [--resolution M]"});
  const std::string out = cl.required("out");
  HdMapOptions options;
  options.raster.resolution = cl.number("resolution", options.raster.resolution);
  if (!(options.raster.resolution >= 0.01 && options.raster.resolution <= 10.0)) {
    throw Error("option --resolution", "must be between 0.01 and 10 metres");
  }
  options.ndtCellSizes.clear();  // the export needs no NDT grid
  const ArgoverseLog log(cl.positional()[0]);
  const HdMap map = HdMap::load(log.mapFiles(), options);  // all input errors surface before writing
  for (const auto& path : exportMapGeoTiffs(map, out)) std::printf("wrote %s\n", path.string().c_str());
  const GridGeometry& g = map.drivable().geometry();
  std::printf("drivable raster: %d x %d cells of %.3f m, origin (%.3f, %.3f), %.1f m^2 drivable\n", g.cols, g.rows,
              g.resolution, g.origin.x(), g.origin.y(), map.drivable().area());
  return 0;
}

}  // namespace hdprior::app
