#include "render/layer_registry.h"

#include <algorithm>
#include <functional>
#include <utility>

#include "engine/error.h"
#include "render/layers/accumulated_sweeps_layer.h"
#include "render/layers/changes_layer.h"
#include "render/layers/drivable_boundary_layer.h"
#include "render/layers/drivable_raster_layer.h"
#include "render/layers/ego_pose_layer.h"
#include "render/layers/estimated_trajectory_layer.h"
#include "render/layers/ground_height_layer.h"
#include "render/layers/ground_labels_layer.h"
#include "render/layers/keyframes_layer.h"
#include "render/layers/landscape_layer.h"
#include "render/layers/lane_centerline_layer.h"
#include "render/layers/lidar_sweep_layer.h"
#include "render/layers/match_layer.h"
#include "render/layers/measure_layer.h"
#include "render/layers/ndt_cells_layer.h"
#include "render/layers/pedestrian_crossing_layer.h"
#include "render/layers/road_points_layer.h"
#include "render/layers/trajectory_layer.h"

namespace hdprior::render {
namespace {

using Factory = std::function<std::unique_ptr<Layer>()>;
struct Entry {
  std::string name;
  Factory factory;
  bool standard;  // part of "all"
  bool analysis = false;  // draws render::Analysis
};

template <typename T>
Entry entry(bool standard = true) {
  return {T::kName, [] { return std::make_unique<T>(); }, standard};
}

// The analysis layers are extras: "all" stays the log and its map.
template <typename T>
Entry analysisEntry() {
  return {T::kName, [] { return std::make_unique<T>(); }, false, true};
}

Entry trajectoryEntry(EstimatedTrajectoryLayer::Which which, const char* name) {
  return {name, [which] { return std::make_unique<EstimatedTrajectoryLayer>(which); }, false, true};
}

// Drawing order: bottom first.
const std::vector<Entry>& registry() {
  using Which = EstimatedTrajectoryLayer::Which;
  static const std::vector<Entry> layers = {
      entry<GroundHeightLayer>(),
      entry<DrivableRasterLayer>(),
      analysisEntry<LandscapeLayer>(),
      entry<DrivableBoundaryLayer>(),
      entry<LaneCenterlineLayer>(),
      entry<PedestrianCrossingLayer>(false),
      entry<NdtCellsLayer>(false),
      analysisEntry<ChangesLayer>(),
      entry<TrajectoryLayer>(),
      trajectoryEntry(Which::Odometry, EstimatedTrajectoryLayer::kOdometryName),
      trajectoryEntry(Which::Optimized, EstimatedTrajectoryLayer::kOptimizedName),
      trajectoryEntry(Which::File, EstimatedTrajectoryLayer::kFileName),
      trajectoryEntry(Which::Comparison, EstimatedTrajectoryLayer::kComparisonName),
      analysisEntry<KeyframesLayer>(),
      entry<AccumulatedSweepsLayer>(false),
      entry<LidarSweepLayer>(),
      entry<GroundLabelsLayer>(false),
      analysisEntry<RoadPointsLayer>(),
      analysisEntry<MatchLayer>(),
      {MatchLayer::kComparisonName, [] { return std::make_unique<MatchLayer>(true); }, false, true},
      analysisEntry<MeasureLayer>(),
      entry<EgoPoseLayer>(),
  };
  return layers;
}

std::string joined() {
  std::string s;
  for (const auto& name : layerNames()) s += (s.empty() ? "" : ", ") + name;
  return s;
}

}  // namespace

const std::vector<std::string>& layerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Entry& e : registry()) n.push_back(e.name);
    return n;
  }();
  return names;
}

const std::vector<std::string>& standardLayerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Entry& e : registry())
      if (e.standard) n.push_back(e.name);
    return n;
  }();
  return names;
}

bool needsAnalysis(const std::string& name) {
  for (const Entry& e : registry())
    if (e.name == name) return e.analysis;
  return false;
}

std::unique_ptr<Layer> makeLayer(const std::string& name) {
  for (const Entry& e : registry())
    if (e.name == name) return e.factory();
  throw Error("layer " + name, "unknown layer (known: " + joined() + ")");
}

std::vector<std::string> parseLayerList(const std::string& list) {
  if (list == "all") return standardLayerNames();
  std::vector<std::string> wanted;
  for (size_t begin = 0, end = 0; end != std::string::npos; begin = end + 1) {
    end = list.find(',', begin);
    const std::string name = list.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    if (std::find(layerNames().begin(), layerNames().end(), name) == layerNames().end())
      throw Error("layer '" + name + "'", "unknown layer (known: " + joined() + ")");
    wanted.push_back(name);
  }
  std::vector<std::string> ordered;
  for (const auto& name : layerNames())
    if (std::find(wanted.begin(), wanted.end(), name) != wanted.end()) ordered.push_back(name);
  return ordered;
}

}  // namespace hdprior::render
