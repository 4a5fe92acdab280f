#pragma once
#include <memory>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/image.h"
#include "render/scene.h"

namespace hdprior {
struct HdMapOptions;
}

namespace hdprior::render {

enum class View { Top, Orbit };
View parseView(const std::string& name);  // "top" | "orbit"; throws Error("option --view", ...)

struct SnapshotOptions {
  int width = 1280, height = 720;
  View view = View::Top;
  std::vector<std::string> layers;  // names in drawing order; empty = all
};

// Parses "WIDTHxHEIGHT"; throws Error("option --size", ...) unless both are in 16..8192.
void parseSize(const std::string& text, int& width, int& height);

// The map parts the renderer needs (no NDT grids, no distance field): faster to load.
HdMapOptions renderMapOptions();

// The camera of a view for a frame: top-down centred on the ego, or an orbit view from
// behind and above it.
Camera viewCamera(View view, const Scene& scene, const Frame& frame, double aspect);

// Headless snapshots of one log: an offscreen context, a renderer and the chosen layers,
// set up once; render() many frames.
class Snapshotter {
 public:
  Snapshotter(const ArgoverseLog& log, const HdMap& map, const SnapshotOptions& options);
  ~Snapshotter();
  Image render(size_t frame);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace hdprior::render
