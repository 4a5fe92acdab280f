#include "render/layers/changes_layer.h"

#include <vector>

#include "engine/changes/map_change_report.h"
#include "render/analysis.h"
#include "render/layers/analysis_drawing.h"
#include "render/layers/layer_drawing.h"
#include "render/scene.h"

namespace hdprior::render {
namespace {

constexpr float kLift = 0.06f;  // metres above the ground, over the map's own layers

std::vector<Eigen::Vector3f> onGround(const Scene& scene, const std::vector<Eigen::Vector2d>& line, bool closed) {
  std::vector<Eigen::Vector3f> out;
  for (const Eigen::Vector2d& p : line) out.push_back(scene.local({p.x(), p.y(), scene.groundZ(p, scene.origin.z()) + kLift}));
  if (closed && !out.empty()) out.push_back(out.front());
  return out;
}

// A square `size` metres wide on the ground at `centre` (lifted `lift` metres), as two triangles.
void addGroundSquare(const Scene& scene, const Eigen::Vector2d& centre, double size, double lift, const Eigen::Vector4f& colour,
                     std::vector<ColoredVertex>& v) {
  const float h = float(size) / 2;
  const Eigen::Vector3f m = scene.local({centre.x(), centre.y(), scene.groundZ(centre, scene.origin.z()) + lift});
  const Eigen::Vector3f corners[4] = {m + Eigen::Vector3f(-h, -h, 0), m + Eigen::Vector3f(h, -h, 0), m + Eigen::Vector3f(h, h, 0),
                                      m + Eigen::Vector3f(-h, h, 0)};
  for (int i : {0, 1, 2, 0, 2, 3}) v.push_back({corners[i], colour});
}

// A square per cell the lidar saw as road or as beside the road.
std::vector<ColoredVertex> surfaceCells(const Scene& scene, const SurfaceEvidence& e, const Eigen::Vector4f& road,
                                        const Eigen::Vector4f& notRoad) {
  std::vector<ColoredVertex> v;
  const GridGeometry& g = e.geometry();
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const Surface s = e.surface(g.index(c, r));
      if (s != Surface::Unknown) addGroundSquare(scene, g.cellCentre(c, r), g.resolution, 0.02, s == Surface::Road ? road : notRoad, v);
    }
  return v;
}

}  // namespace

void ChangesLayer::setAnalysis(const Scene& scene, const Analysis& analysis) {
  analysis_ = &analysis;
  build(scene);
}

void ChangesLayer::build(const Scene& scene) {
  Strokes strokes;
  std::vector<ColoredVertex> cells;
  if (analysis_ && analysis_->changes) {
    const MapChangeReport& report = *analysis_->changes;
    for (const BoundaryStretch& s : report.stretches) {
      if (s.samples == 0) continue;
      if (s.verdict == MapVerdict::Contradicted) strokes.polyline(onGround(scene, s.line, false), 0.6f, contradicted_);
      else if (s.verdict == MapVerdict::Consistent) strokes.polyline(onGround(scene, s.line, false), 0.25f, consistent_);
      else if (s.undecided()) strokes.polyline(onGround(scene, s.line, false), 0.35f, undecided_);
      else if (show_ == 2) strokes.polyline(onGround(scene, s.line, false), 0.15f, unobserved_);
    }
    for (const MissingSurface& m : report.missing) strokes.polyline(onGround(scene, m.outline, true), 0.45f, missing_);
    for (const CrossingVerdict& c : report.crossings) {
      if (c.verdict == MapVerdict::Contradicted) strokes.polyline(onGround(scene, c.outline, true), 0.45f, contradicted_);
      else if (c.verdict == MapVerdict::Consistent) strokes.polyline(onGround(scene, c.outline, true), 0.2f, consistent_);
      else if (show_ == 2 && c.roadCells > 0) strokes.polyline(onGround(scene, c.outline, true), 0.12f, unobserved_);
    }
    for (const MissingCrossing& m : report.missingCrossings) strokes.polyline(onGround(scene, m.outline, true), 0.3f, missing_);
    for (const LaneLineStretch& s : report.laneLines) {
      if (s.verdict == MapVerdict::Contradicted) strokes.polyline(onGround(scene, s.line, false), 0.35f, contradicted_);
      else if (show_ == 2 && s.verdict == MapVerdict::Consistent) strokes.polyline(onGround(scene, s.line, false), 0.1f, consistent_);
    }
    if (show_ >= 1) {
      cells = surfaceCells(scene, report.evidence, road_, notRoad_);
      for (const PaintedCell& c : report.paint)
        addGroundSquare(scene, c.centre, report.paintCell, 0.04, c.onMapPaint ? paintOnMap_ : paintOffMap_, cells);
    }
  }
  if (analysis_ && analysis_->changeLabels && labels_)
    for (const MapChangeLabel& l : *analysis_->changeLabels)
      for (const std::vector<Eigen::Vector2d>& place : l.places)
        strokes.polyline(onGround(scene, place, !l.openLine()), 0.25f, labelled_);
  strokes_.upload(strokes, {});
  surface_ = std::make_unique<GpuMesh>();
  surface_->upload(std::span<const ColoredVertex>(cells));
}

void ChangesLayer::draw(const DrawContext& context) const {
  if (surface_) drawColored(context, *surface_, Primitive::Triangles);
  strokes_.draw(context, 1.0f);
}

std::vector<MarkerKey> ChangesLayer::markerKeys() const {
  if (!analysis_ || !analysis_->changes) return {};
  std::vector<MarkerKey> keys = {{"contradicted", contradicted_},
                                 {"consistent", consistent_},
                                 {"too few samples to tell (some contradict)", undecided_},
                                 {"missing surface or crossing", missing_}};
  if (show_ >= 1) {
    keys.push_back({"lidar: road", road_});
    keys.push_back({"lidar: beside the road", notRoad_});
    keys.push_back({"lidar: paint on mapped paint", paintOnMap_});
    keys.push_back({"lidar: paint elsewhere", paintOffMap_});
  }
  if (show_ == 2) keys.push_back({"unobserved", unobserved_});
  if (analysis_->changeLabels && labels_) keys.push_back({"labelled change (map_change.json)", labelled_});
  return keys;
}

std::vector<LayerOption> ChangesLayer::options() {
  std::vector<LayerOption> o = {
      LayerOption::choice("show", &show_, {"verdicts", "verdicts and lidar surface", "everything"}, true)};
  o.push_back(LayerOption::choice("labelled changes", &labels_, {"hidden", "shown"}, true));
  for (auto [label, color] : {std::pair{"contradicted", &contradicted_}, {"consistent", &consistent_}, {"too few to tell", &undecided_}, {"missing", &missing_},
                              {"labelled change", &labelled_}}) {
    o.push_back(LayerOption::colorPicker(label, color));
    o.back().rebuilds = true;
  }
  return o;
}

}  // namespace hdprior::render
