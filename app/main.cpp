#include <cstdio>
#include <exception>
#include <functional>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "engine/allocator_tuning.h"
#include "engine/error.h"

namespace {

using Command = std::function<int(const std::vector<std::string>&)>;

const std::map<std::string, std::pair<Command, const char*>>& commands() {
  static const std::map<std::string, std::pair<Command, const char*>> table = {
      {"info", {hdprior::app::runInfo, "summarise an Argoverse 2 log: hdprior info LOG"}},
      {"export-map", {hdprior::app::runExportMap, "write the HD-map rasters as GeoTIFFs: hdprior export-map LOG --out DIR"}},
      {"snapshot", {hdprior::app::runSnapshot, "draw a frame headless to PNG: hdprior snapshot LOG --frame N --out FILE.png"}},
      {"run", {hdprior::app::runRun, "odometry + HD-map priors + evaluation: hdprior run LOG --out DIR [--no-prior] [--config FILE] [--odometry-drift S,Y[,P]] [--odometry FILE]"}},
      {"eval", {hdprior::app::runEval, "every log under DIR (or shard I of N of them), in parallel, and the paper's table over them: hdprior eval DIR --out OUTDIR [-j N] [--shard I/N [--skip-existing]] [--config FILE] [--no-prior] [--odometry-drift S,Y[,P]] [--odometry-dir D]"}},
      {"merge", {hdprior::app::runMerge, "the tables of a sharded eval from its per-log results: hdprior merge OUTDIR --logs DIR"}},
      {"degrade-trajectory", {hdprior::app::runDegradeTrajectory, "a log's ground truth (or a TUM file) with drift and a random walk: hdprior degrade-trajectory (LOG | FILE.tum) --out FILE [--drift S,Y[,P]] [--random-walk M,DEG] [--seed N]"}},
      {"demo", {hdprior::app::runDemo, "simulate (or reuse) a town log, run with and without priors: hdprior demo [--out DIR] [--town SEED --seconds N]"}},
      {"sim", {hdprior::app::runSim, "simulate an Argoverse 2 log: hdprior sim (--town SEED | --map LOG) --out DIR"}},
      {"match", {hdprior::app::runMatch, "match a frame's road points to the map: hdprior match LOG --frame N [--init dx,dy,dyaw_deg] [--backend ndt2d|pcl] [--config FILE]"}},
      {"view", {hdprior::app::runView, "the desktop app and tuning bench: hdprior view [LOG] [--script FILE | --frames N --exit] [--screenshot FILE.png] [--config FILE] [--odometry FILE [--odometry-format tum|kitti] [--odometry-frame first|city] [--odometry-times FILE]]"}},
  };
  return table;
}

void printUsage(std::FILE* out) {
  std::fprintf(out, "usage: hdprior <command> [options]\ncommands:\n");
  for (const auto& [name, entry] : commands()) std::fprintf(out, "  %-18s %s\n", name.c_str(), entry.second);
}

}  // namespace

int main(int argc, char** argv) {
  hdprior::keepFreedMemoryMapped();
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    printUsage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string name = argv[1];
  const auto it = commands().find(name);
  if (it == commands().end()) {
    std::fprintf(stderr, "hdprior: unknown command '%s' (try hdprior --help)\n", name.c_str());
    return 2;
  }
  try {
    return it->second.first(std::vector<std::string>(argv + 2, argv + argc));
  } catch (const hdprior::Error& e) {
    std::fprintf(stderr, "hdprior %s: %s\n", name.c_str(), e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "hdprior %s: out of memory\n", name.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hdprior %s: internal error: %s\n", name.c_str(), e.what());
    return 1;
  }
}
