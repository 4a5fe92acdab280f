#pragma once
#include <memory>
#include <vector>

#include "render/camera.h"
#include "render/layer.h"
#include "render/overlays/screen_canvas.h"

namespace hdprior::render {

class GpuMesh;

// Pixels along each edge of the viewport that the overlay keeps clear (the app's panels).
struct ScreenInsets {
  float left = 0, top = 0, right = 0, bottom = 0;
};

// What is drawn over the 3-D view so that it explains itself, from the visible layers and the
// camera: the legend of the markers drawn (top left), a metre scale bar in top-down views
// (bottom left) and the colour bar of every distinct colour scale (bottom right), each on a dark
// translucent box. Sizes follow the height of the free part of the viewport.
ScreenCanvas viewOverlay(const std::vector<std::unique_ptr<Layer>>& layers, const Camera& camera, int width,
                         int height, const ScreenInsets& insets = {});

// Draws viewOverlay(...) into the current viewport. Create, use and destroy it with the same
// context current.
class ViewOverlayDrawer {
 public:
  ViewOverlayDrawer();
  ~ViewOverlayDrawer();
  void draw(const ScreenCanvas& canvas, const ShaderLibrary& shaders);

 private:
  std::unique_ptr<GpuMesh> mesh_;
};

}  // namespace hdprior::render
