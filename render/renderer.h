#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "render/analysis.h"
#include "render/camera.h"
#include "render/layer.h"
#include "render/overlays/view_overlay.h"
#include "render/scene.h"

namespace hdprior::render {

struct ShaderLibrary;

// Draws a list of layers into the current GL context (an offscreen buffer or a window).
// Create, use and destroy it with the same context current.
// Clears the current context's viewport (0, 0, width, height) to the renderer's background.
void clearView(int width, int height);

class Renderer {
 public:
  Renderer();
  ~Renderer();

  void addLayer(std::unique_ptr<Layer> layer);
  const std::vector<std::unique_ptr<Layer>>& layers() const { return layers_; }

  void setScene(const Scene& scene);  // uploads static data of every layer
  // Uploads per-frame data; if a layer throws, the others still update and the first error is rethrown.
  void setFrame(const Frame& frame);
  // Keeps the analysis and hands it to every layer (after setScene).
  void setAnalysis(Analysis analysis);
  const Analysis& analysis() const { return analysis_; }
  // Builds one layer's per-frame data again after an option that `rebuilds` changed.
  void rebuild(Layer& layer);
  const Frame& frame() const { return frame_; }
  // Lidar points of the visible layers.
  size_t pointsDrawn() const;
  // Changes whenever what draw(camera, ...) would show changes: the camera, the scene and frame
  // data, each layer's visibility, opacity and option values, the overlay's switch and insets
  // (a cache key, see ViewCache).
  uint64_t viewKey(const Camera& camera);
  // The app's panels cover these edges of the view: the overlay stays clear of them.
  void setOverlayInsets(const ScreenInsets& insets) { insets_ = insets; }
  // Clears the viewport and draws the visible layers in order, bottom first, then (when
  // showOverlay) the overlay that explains them (render/overlays/view_overlay.h).
  // pointStride > 1: lidar point layers draw every n-th point.
  void draw(const Camera& camera, int width, int height, int pointStride = 1) const;

  bool showOverlay = true;

 private:
  std::unique_ptr<ShaderLibrary> shaders_;
  std::vector<std::unique_ptr<Layer>> layers_;
  std::unique_ptr<ViewOverlayDrawer> overlay_;
  ScreenInsets insets_;
  Scene scene_;
  Frame frame_;
  Analysis analysis_;
  uint64_t generation_ = 0;  // counts data uploads (scene, frame, rebuilds)
};

}  // namespace hdprior::render
