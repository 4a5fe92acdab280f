#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/analysis.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/scene.h"

namespace hdprior {
struct HdMapOptions;
}

namespace hdprior::render {

// Top: north up around the ego, 80 m tall. Orbit: from behind and above the ego. Landscape: north up
// over the inspected keyframe's cost landscape (centred on its match estimate, framing its extent).
// Inspector: oblique, from behind and above the inspected keyframe's match estimate, 60 m away.
// Landscape and inspector fall back to top and orbit without an inspection.
enum class View { Top, Orbit, Landscape, Inspector };
// "top" | "orbit" | "landscape" | "inspector"; throws Error("option --view", ...)
View parseView(const std::string& name);
// The layers a view draws when none are named: the standard ones for top and orbit; drivable
// raster, boundary, landscape, road points and match for landscape; drivable raster, boundary,
// road points (non-ground shown), keyframes and match for inspector.
std::vector<std::string> defaultLayers(View view);

struct SnapshotOptions {
  int width = 1280, height = 720;
  View view = View::Top;
  std::vector<std::string> layers;  // names in drawing order; empty = all
  bool overlay = true;               // colour bars, scale bar and marker legend over the view
  std::map<std::string, float> opacity;  // per layer name; 1 where not given
  SweepRoadPointOptions roadPoints;      // how the ground_labels layer labels a sweep
  std::vector<uint8_t> groundLabels;     // the reference ground labels of frame groundLabelsFrame
  size_t groundLabelsFrame = 0;
};

// Parses "WIDTHxHEIGHT"; throws Error("option --size", ...) unless both are in 16..8192.
void parseSize(const std::string& text, int& width, int& height);

// The map parts the renderer needs (no NDT grids, no distance field): faster to load.
HdMapOptions renderMapOptions();

// The camera of a view for a frame (and the analysis, for the landscape and inspector views).
Camera viewCamera(View view, const Scene& scene, const Frame& frame, double aspect, const Analysis* analysis = nullptr);

// Headless snapshots of one log: an offscreen context, a renderer and the chosen layers,
// set up once; render() many frames.
class Snapshotter {
 public:
  Snapshotter(const ArgoverseLog& log, const HdMap& map, const SnapshotOptions& options);
  ~Snapshotter();
  // What the analysis layers draw (and the landscape and inspector views frame).
  void setAnalysis(Analysis analysis);
  Image render(size_t frame);
  // The frame from another camera than the view's (a saved session's).
  Image render(size_t frame, const Camera& camera);
  const Scene& scene() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace hdprior::render
