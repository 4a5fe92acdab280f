#pragma once
#include <memory>
#include <vector>

#include "render/camera.h"
#include "render/layer.h"
#include "render/scene.h"

namespace hdprior::render {

struct ShaderLibrary;

// Draws a list of layers into the current GL context (an offscreen buffer or a window).
// Create, use and destroy it with the same context current.
class Renderer {
 public:
  Renderer();
  ~Renderer();

  void addLayer(std::unique_ptr<Layer> layer);
  const std::vector<std::unique_ptr<Layer>>& layers() const { return layers_; }

  void setScene(const Scene& scene);  // uploads static data of every layer
  void setFrame(const Frame& frame);  // uploads per-frame data
  // Clears the viewport and draws the layers in order, bottom first.
  void draw(const Camera& camera, int width, int height) const;

 private:
  std::unique_ptr<ShaderLibrary> shaders_;
  std::vector<std::unique_ptr<Layer>> layers_;
  Scene scene_;
};

}  // namespace hdprior::render
