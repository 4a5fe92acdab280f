#include "render/scene.h"

#include <cmath>
#include <string>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"

namespace hdprior::render {

double Scene::groundZ(const Eigen::Vector2d& xy, double fallback) const {
  const double h = map && map->hasGroundHeight() ? map->groundHeight().bilinearAt(xy) : NAN;
  return std::isfinite(h) ? h : fallback;
}

Scene makeScene(const ArgoverseLog& log, const HdMap& map) {
  Scene scene{&log, &map, Eigen::Vector3d::Zero()};
  if (!log.cityTEgo().empty()) scene.origin = log.cityTEgo().poses().front().translation();
  return scene;
}

Frame makeFrame(const Scene& scene, size_t index) {
  const ArgoverseLog& log = *scene.log;
  if (index >= log.sweepCount())
    throw Error("option --frame", "frame " + std::to_string(index) + " is out of range (the log has " +
                                      std::to_string(log.sweepCount()) + " sweeps)");
  Frame frame;
  frame.index = index;
  frame.timestampNs = log.sweepTimestamps()[index];
  frame.cityTEgo = log.cityTEgo().at(frame.timestampNs);
  frame.sweep = log.sweep(index);
  frame.groundZ = scene.groundZ(frame.cityTEgo.translation().head<2>(), frame.cityTEgo.translation().z());
  return frame;
}

}  // namespace hdprior::render
