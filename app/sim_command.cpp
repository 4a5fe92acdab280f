#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/progress_bar.h"
#include "engine/error.h"
#include "engine/io/map_folder.h"
#include "engine/sim/log_writer.h"

namespace hdprior::app {
namespace {

uint64_t seedOption(const CommandLine& cl, const std::string& name) {
  const long long v = cl.integer(name, 0);
  if (v < 0) throw Error("option --" + name, "must not be negative");
  return uint64_t(v);
}

}  // namespace

int runSim(const std::vector<std::string>& args) {
  const CommandLine cl(
      args, {.valued = {"town", "map", "out", "seconds", "seed", "trajectory", "noise", "parked", "map-change",
                        "threads", "dropout", "family"},
             .flags = {"quiet"}, .minPositional = 0, .maxPositional = 0,
             .usage = "hdprior sim (--town SEED | --map LOG) --out DIR [--seconds N] [--seed S] "
                      "[--trajectory real|route] [--family tuning|validation] [--noise M] [--parked P] [--map-change F] "
                      "[--dropout D] [--threads T] [--quiet]"});
  SimulationOptions o;
  if (cl.has("town") == cl.has("map")) throw Error("option --town/--map", "give exactly one of --town SEED and --map LOG");
  std::optional<MapFolder> folder;
  if (cl.has("town")) {
    o.townSeed = seedOption(cl, "town");
  } else {
    o.mapLog = cl.required("map");
    folder = openMapFolder(o.mapLog);
  }
  o.outDir = cl.required("out");
  o.seconds = cl.number("seconds", 0.0);
  if (cl.has("seconds") && !(o.seconds > 0.0)) throw Error("option --seconds", "must be positive");
  o.seed = seedOption(cl, "seed");
  // A map with poses drives them; a map alone (or a town) a route.
  const std::string trajectory = cl.value("trajectory").value_or(folder && folder->poses ? "real" : "route");
  if (trajectory == "real") o.trajectory = SimTrajectory::Real;
  else if (trajectory == "route") o.trajectory = SimTrajectory::Route;
  else throw Error("option --trajectory", "'" + trajectory + "' is not real or route");
  o.noise.rangeSigma = cl.number("noise", 0.02);
  o.noise.dropout = cl.number("dropout", 0.02);
  o.scene.parked = cl.number("parked", 0.5);
  if (const auto family = cl.value("family")) {
    o.family = parseSceneFamily(*family);
    if (cl.has("parked")) throw Error("option --parked", "a --family draws the parked cars; leave --parked out");
  }
  o.mapChange = cl.number("map-change", 0.0);
  o.threads = int(cl.integer("threads", 2));
  if (!cl.has("quiet")) o.progress = [bar = std::make_shared<ProgressBar>("sim")](size_t d, size_t t) { (*bar)(d, t); };
  const SimulationResult r = simulateLog(o);
  // Said once it worked, so that a failure stays one line.
  if (folder && !folder->calibration) {
    std::fprintf(stderr, "hdprior sim: %s has no calibration/egovehicle_SE3_sensor.feather: the simulated lidars "
                         "have the default Argoverse 2 calibration\n", o.mapLog.string().c_str());
  }
  std::printf("%s\n", r.logId.c_str());
  return 0;
}

}  // namespace hdprior::app
