#include <cstdio>
#include <filesystem>

#include "app/command_line.h"
#include "app/commands.h"
#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "render/layer_registry.h"
#include "render/png_writer.h"
#include "render/snapshot.h"

namespace hdprior::app {

int runSnapshot(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"frame", "out", "size", "view", "layers"}, .flags = {},
                              .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior snapshot LOG --frame N --out FILE.png [--size 1280x720] "
                                       "[--view top|orbit] [--layers a,b,c]"});
  // Check every option before the slow part (map loading).
  render::SnapshotOptions options;
  render::parseSize(cl.value("size").value_or("1280x720"), options.width, options.height);
  options.view = render::parseView(cl.value("view").value_or("top"));
  options.layers = render::parseLayerList(cl.value("layers").value_or("all"));
  if (options.layers.empty()) throw Error("option --layers", "no layer given");
  const long long frame = cl.integer("frame", -1);
  if (!cl.has("frame")) throw Error("option --frame", "missing (the frame to draw)");
  if (frame < 0) throw Error("option --frame", "must not be negative");
  const std::filesystem::path out = cl.required("out");
  const std::filesystem::path outDir = out.parent_path().empty() ? "." : out.parent_path();
  if (!std::filesystem::is_directory(outDir)) throw Error(out.string(), "its folder does not exist");
  if (std::filesystem::is_directory(out)) throw Error(out.string(), "is a directory, expected a .png file name");

  const ArgoverseLog log(cl.positional()[0]);
  if (size_t(frame) >= log.sweepCount())
    throw Error("option --frame", "frame " + std::to_string(frame) + " is out of range (the log has " +
                                      std::to_string(log.sweepCount()) + " sweeps)");
  const HdMap map = HdMap::load(log.mapFiles(), render::renderMapOptions());
  render::Snapshotter snapshotter(log, map, options);
  render::writePng(out, snapshotter.render(size_t(frame)));
  std::printf("wrote %s (%dx%d, frame %lld)\n", out.string().c_str(), options.width, options.height, frame);
  return 0;
}

}  // namespace hdprior::app
