#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "render/layer_legend.h"
#include "render/layer_option.h"

namespace hdprior::render {

struct Scene;
struct Frame;
struct Analysis;
struct ShaderLibrary;

struct DrawContext {
  Eigen::Matrix4f viewProjection;
  const ShaderLibrary& shaders;
  float pixelScale = 1.0f;  // image height / 720: point sizes scale with it
  float opacity = 1.0f;     // the drawn layer's opacity, multiplied into its colours
  int pointStride = 1;      // lidar point layers draw every n-th point (a lighter draw while the camera moves)
};

// One drawable thing. GL resources are created in the calls below, with the context current.
// A new layer is one class in render/layers/ plus one line in layer_registry.cpp; its
// options() appear in the app's layers panel without any UI code.
class Layer {
 public:
  virtual ~Layer() = default;
  virtual std::string name() const = 0;
  // Once, for data that does not change between frames (map rasters, lanes, trajectory).
  virtual void setScene(const Scene& scene) {}
  // On every frame change, for per-frame data (the sweep, the ego pose).
  virtual void setFrame(const Scene& scene, const Frame& frame) {}
  // When the pipeline's results change (trajectories, keyframes, the inspected keyframe). The
  // analysis outlives the call (the renderer keeps it until the next one): layers may keep a pointer.
  virtual void setAnalysis(const Scene& scene, const Analysis& analysis) {}
  virtual void draw(const DrawContext& context) const = 0;
  // The controls beyond visibility and opacity (colours, colouring, point size, ...).
  virtual std::vector<LayerOption> options() { return {}; }
  // Lidar points this layer draws (the status bar's count).
  virtual size_t pointCount() const { return 0; }
  // The colour map it colours by with its range, if any (the overlay's colour bar).
  virtual std::optional<ColourScale> colourScale() const { return std::nullopt; }
  // The markers it currently draws (the overlay's legend); empty when it draws none.
  virtual std::vector<MarkerKey> markerKeys() const { return {}; }

  bool visible = true;
  float opacity = 1.0f;
};

}  // namespace hdprior::render
