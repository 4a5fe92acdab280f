#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/option_checks.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/map/map_export.h"

namespace hdprior::app {

namespace {

struct ExportMapArguments {
  std::string log, out;
  double resolution = HdMapOptions{}.raster.resolution;
};

int runExportMap(const ExportMapArguments& a) {
  const std::string& out = a.out;
  HdMapOptions options;
  options.raster.resolution = a.resolution;
  if (!(options.raster.resolution >= 0.01 && options.raster.resolution <= 10.0)) {
    throw Error("option --resolution", "must be between 0.01 and 10 metres");
  }
  options.ndtCellSizes.clear();  // the export needs no NDT grid
  const ArgoverseLog log(a.log);
  const HdMap map = HdMap::load(log.mapFiles(), options);  // all input errors surface before writing
  for (const auto& path : exportMapGeoTiffs(map, out)) std::printf("wrote %s\n", path.string().c_str());
  const GridGeometry& g = map.drivable().geometry();
  std::printf("drivable raster: %d x %d cells of %.3f m, origin (%.3f, %.3f), %.1f m^2 drivable\n", g.cols, g.rows,
              g.resolution, g.origin.x(), g.origin.y(), map.drivable().area());
  return 0;
}

}  // namespace

Command addExportMapCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "export-map", "write the HD-map rasters as GeoTIFFs in city metres: DIR/drivable.tif, ground_height.tif, boundary_distance.tif");
  auto a = std::make_shared<ExportMapArguments>();
  addLogArgument(*command, a->log);
  command->add_option("--out", a->out, "the output folder")->type_name("DIR")->required();
  command->add_option("--resolution", a->resolution, "the rasters' cell size in metres, 0.01 to 10")->type_name("M")->check(finiteNumber());
  return {command, [a] { return runExportMap(*a); }};
}

}  // namespace hdprior::app
