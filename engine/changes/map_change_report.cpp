#include "engine/changes/map_change_report.h"

#include <future>
#include <map>

#include "engine/changes/surface_classes.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"

namespace hdprior {

namespace {

struct SpacedSweep {
  size_t index = 0;
  double driven = 0.0;  // metres along the poses from the first sweep added
};

// The sweeps to add: the first the poses cover, then one every `spacing` metres.
std::vector<SpacedSweep> spacedSweeps(const ArgoverseLog& log, const PoseTrajectory& poses, double spacing) {
  std::vector<SpacedSweep> out;
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < log.sweepCount(); ++i) {
    const int64_t t = log.sweepTimestamps()[i];
    if (!poses.covers(t)) continue;
    const Eigen::Vector3d p = poses.at(t).translation();
    if (out.empty()) out.push_back({i, 0.0});
    else if ((p - last).norm() >= spacing) out.push_back({i, out.back().driven + (p - last).norm()});
    else continue;
    last = p;
  }
  return out;
}

SurfaceEvidence evidenceGrid(const ArgoverseLog& log, const PoseTrajectory& poses, const std::vector<SpacedSweep>& sweeps,
                             const SweepRoadPointOptions& roadPoints, const ChangeOptions& options) {
  std::vector<Eigen::Vector2d> positions;
  for (const SpacedSweep& s : sweeps) positions.push_back(poses.at(log.sweepTimestamps()[s.index]).translation().head<2>());
  return SurfaceEvidence::around(positions, roadPoints.road.maxRange + options.reach, options.cell);
}

}  // namespace

std::unique_ptr<HdMap> loadCheckedMap(const ArgoverseLog& log, const PoseTrajectory& poses, const SweepRoadPointOptions& roadPoints,
                                      const ChangeOptions& options) {
  HdMapOptions mapOptions;
  mapOptions.ndtCellSizes.clear();
  if (!poses.empty()) {
    Eigen::AlignedBox2d window;
    for (const SE3& p : poses.poses()) window.extend(p.translation().head<2>());
    const double reach = roadPoints.road.maxRange + options.reach + 10.0;
    mapOptions.raster.window = Eigen::AlignedBox2d(window.min().array() - reach, window.max().array() + reach);
  }
  return std::make_unique<HdMap>(HdMap::load(log.mapFiles(), mapOptions));
}

std::vector<DrivableAreaVerdict> drivableAreaVerdicts(const VectorMap& map, const std::vector<BoundaryStretch>& stretches) {
  std::map<int64_t, DrivableAreaVerdict> byId;
  for (const DrivableArea& a : map.drivableAreas) byId[a.id].id = a.id;
  auto rank = [](MapVerdict v) { return v == MapVerdict::Contradicted ? 2 : v == MapVerdict::Consistent ? 1 : 0; };
  for (const BoundaryStretch& s : stretches) {
    DrivableAreaVerdict& v = byId[s.areaId];
    v.id = s.areaId;
    if (rank(s.verdict) > rank(v.verdict) || (s.verdict == v.verdict && s.confidence > v.confidence)) {
      v.verdict = s.verdict;
      v.confidence = s.confidence;
      v.bestFrame = s.bestFrame;
    }
    if (s.firstFrame >= 0 && s.verdict == v.verdict && (v.firstFrame < 0 || s.firstFrame < v.firstFrame)) v.firstFrame = s.firstFrame;
  }
  std::vector<DrivableAreaVerdict> out;
  for (const DrivableArea& a : map.drivableAreas) out.push_back(byId[a.id]);
  return out;
}

MapChangeReport judgeMapChanges(SurfaceEvidence evidence, const HdMap& map, const ChangeOptions& options) {
  MapChangeReport report;
  classifySurface(evidence, options);
  const BoundaryDistance& distance = map.boundaryDistance();
  for (BoundaryStretch& s : checkBoundaries(map.vectorMap().drivableAreas, evidence, distance, options)) {
    if (s.verdict != MapVerdict::Unobserved) report.observedBoundaryKm += s.observed * options.sampleSpacing / 1000.0;
    report.stretches.push_back(std::move(s));
  }
  report.drivableAreas = drivableAreaVerdicts(map.vectorMap(), report.stretches);
  report.missing = findMissingSurfaces(evidence, distance, map.hasGroundHeight() ? &map.groundHeight() : nullptr, options);
  report.evidence = std::move(evidence);
  return report;
}

MapChangeReport detectMapChanges(const ArgoverseLog& log, const HdMap& map, const PoseTrajectory& poses,
                                 const SweepRoadPointOptions& roadPoints, const ChangeOptions& options,
                                 const std::function<void(size_t, size_t)>& progress, const std::atomic<bool>* cancel) {
  const std::vector<SpacedSweep> sweeps = spacedSweeps(log, poses, options.frameSpacing);
  SurfaceEvidence evidence = evidenceGrid(log, poses, sweeps, roadPoints, options);
  const GroundHeight* ground = map.hasGroundHeight() ? &map.groundHeight() : nullptr;
  CrossingEvidence crossings(map.vectorMap(), options);
  LaneLineEvidence laneLines(map.vectorMap(), options);
  size_t frames = 0;
  std::vector<MisalignedSweep> misaligned;
  struct Labelled {
    LabelledSweep sweep;
    SweepPaint paint;
    SweepAlignment alignment;
  };
  auto label = [&](size_t k) {
    const SE3 cityTEgo = poses.at(log.sweepTimestamps()[sweeps[k].index]);
    const std::shared_ptr<const LidarSweep> sweep = log.sweep(sweeps[k].index);
    Labelled out{labelSweep(*sweep, levelRotation(cityTEgo), roadPoints), {}, {}};
    out.paint = findSweepPaint(*sweep, out.sweep, options);
    out.alignment = sweepAlignment(out.sweep, cityTEgo, map.boundaryDistance(), map.vectorMap().drivableAreas, ground, options);
    return out;
  };
  auto add = [&](size_t k, const Labelled& labelled) {
    const int frame = int(sweeps[k].index);
    if (labelled.alignment.misaligned(options, sweeps[k].driven)) {
      const bool follows = k > 0 && !misaligned.empty() && misaligned.back().frame == int(sweeps[k - 1].index);
      misaligned.push_back({frame, labelled.alignment, follows, labelled.alignment.offGround(options)});
      return;
    }
    const SE3 cityTEgo = poses.at(log.sweepTimestamps()[sweeps[k].index]);
    evidence.add(frame, labelled.sweep, cityTEgo, ground);
    crossings.add(frame, labelled.paint, cityTEgo);
    laneLines.add(frame, labelled.paint, cityTEgo);
    ++frames;
  };
  for (size_t k = 0; k < sweeps.size(); k += 2) {
    if (cancel && cancel->load()) break;
    std::future<Labelled> second;
    if (k + 1 < sweeps.size()) second = std::async(std::launch::async, label, k + 1);
    add(k, label(k));
    if (second.valid()) add(k + 1, second.get());
    if (progress) progress(frames, sweeps.size());
  }
  MapChangeReport report = judgeMapChanges(std::move(evidence), map, options);
  report.crossings = crossings.verdicts();
  report.missingCrossings = crossings.missing();
  report.laneLines = laneLines.stretches(crossings.asphaltShare());
  report.paint = crossings.paintedCells();
  report.paintCell = options.paintCell;
  report.frames = frames;
  report.misaligned = std::move(misaligned);
  report.drivenKm = sweeps.empty() ? 0.0 : sweeps.back().driven / 1000.0;
  return report;
}

}  // namespace hdprior
