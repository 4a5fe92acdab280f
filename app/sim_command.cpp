#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.h"
#include "app/option_checks.h"
#include "app/progress_bar.h"
#include "engine/error.h"
#include "engine/io/map_folder.h"
#include "engine/sim/log_writer.h"

namespace hdprior::app {
namespace {

struct SimArguments {
  long long town = 0, seed = 0, threads = 2;
  std::string map, out, trajectory, family;
  double seconds = 0.0;  // not given: the default length (the map's poses' span, or the simulator's)
  SweepNoise noise;
  double parked = SceneOptions{}.parked, mapChange = 0.0, mapChangeWithin = 0.0;
  bool quiet = false;
  bool townGiven = false, secondsGiven = false, parkedGiven = false, withinGiven = false;
};

// A map with poses drives them; a map alone (or a town) a route.
SimTrajectory trajectoryOf(const SimArguments& a, const std::optional<MapFolder>& folder) {
  const std::string trajectory = !a.trajectory.empty() ? a.trajectory : folder && folder->poses ? "real" : "route";
  if (trajectory == "real") return SimTrajectory::Real;
  if (trajectory == "route") return SimTrajectory::Route;
  throw Error("option --trajectory", "'" + trajectory + "' is not real or route");
}

int runSim(const SimArguments& a) {
  SimulationOptions o;
  if (a.townGiven == !a.map.empty()) throw Error("option --town/--map", "give exactly one of --town SEED and --map LOG");
  std::optional<MapFolder> folder;
  if (a.townGiven) {
    o.townSeed = uint64_t(a.town);
  } else {
    o.mapLog = a.map;
    folder = openMapFolder(o.mapLog);
  }
  o.outDir = a.out;
  o.seconds = a.seconds;
  if (a.secondsGiven && !(o.seconds > 0.0)) throw Error("option --seconds", "must be positive");
  o.seed = uint64_t(a.seed);
  o.trajectory = trajectoryOf(a, folder);
  o.noise = a.noise;
  o.scene.parked = a.parked;
  if (!a.family.empty()) {
    o.family = parseSceneFamily(a.family);
    if (a.parkedGiven) throw Error("option --parked", "a --family draws the parked cars; leave --parked out");
  }
  o.mapChange = a.mapChange;
  if (a.withinGiven) o.mapChangeWithin = a.mapChangeWithin;
  o.threads = int(a.threads);
  if (!a.quiet) o.progress = [bar = std::make_shared<ProgressBar>("sim")](size_t d, size_t t) { (*bar)(d, t); };
  const SimulationResult r = simulateLog(o);
  // Said once it worked, so that a failure stays one line.
  if (folder && !folder->calibration) {
    std::fprintf(stderr, "hdprior sim: %s has no calibration/egovehicle_SE3_sensor.feather: the simulated lidars "
                         "have the default Argoverse 2 calibration\n", o.mapLog.string().c_str());
  }
  std::printf("%s\n", r.logId.c_str());
  return 0;
}

}  // namespace

Command addSimCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "sim", "simulate a log in the Argoverse 2 layout from a procedural town or a real map (a whole log, a log's map/ and "
             "poses, or a log map's three files); prints its id");
  auto a = std::make_shared<SimArguments>();
  CLI::Option* town = command->add_option("--town", a->town, "a procedural town from this seed")->type_name("SEED")->default_str("")->check(integerAtLeast(0));
  command->add_option("--map", a->map, "a real map (and its poses, if any) instead of a town")->type_name("LOG");
  command->add_option("--out", a->out, "the folder the log is written into")->type_name("DIR")->required();
  CLI::Option* seconds = command->add_option("--seconds", a->seconds, "the drive's length in seconds (default: the map's poses' span, or the simulator's)")
      ->type_name("N")
      ->default_str("")
      ->check(finiteNumber());
  command->add_option("--seed", a->seed, "the drive's and the noise's seed")->type_name("S")->check(integerAtLeast(0));
  command->add_option("--trajectory", a->trajectory, "drive the map's poses or a route (default: real when the map has poses)")
      ->type_name("real|route");
  command->add_option("--family", a->family, "draw the scene's variation from a family")->type_name("tuning|validation");
  command->add_option("--noise", a->noise.rangeSigma, "range noise sigma in metres")->type_name("M")->check(finiteNumber());
  CLI::Option* parked = command->add_option("--parked", a->parked, "share of parking spots with a car, 0 to 1")
                            ->type_name("P")
                            ->check(finiteNumber());
  command->add_option("--map-change", a->mapChange, "share of the map changed since it was drawn, 0 to 1")->type_name("F")->check(finiteNumber());
  CLI::Option* within = command->add_option("--map-change-within", a->mapChangeWithin,
                                             "change only elements within this many metres of the drive (default: anywhere)")
                            ->type_name("M")
                            ->default_str("")
                            ->check(finiteNumber());
  command->add_option("--dropout", a->noise.dropout, "share of returns dropped")->type_name("D")->check(finiteNumber());
  command->add_option("--threads", a->threads, "threads casting rays")->type_name("T")->check(integerAtLeast(1));
  command->add_flag("--quiet", a->quiet, "no progress bar");
  command->callback([a, town, seconds, parked, within] {
    a->townGiven = town->count() > 0;
    a->withinGiven = within->count() > 0;
    a->secondsGiven = seconds->count() > 0;
    a->parkedGiven = parked->count() > 0;
  });
  return {command, [a] { return runSim(*a); }};
}

}  // namespace hdprior::app
