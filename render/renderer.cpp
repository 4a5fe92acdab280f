#include "render/renderer.h"

#include "render/gl.h"
#include "render/shader_program.h"

namespace hdprior::render {

Renderer::Renderer() : shaders_(std::make_unique<ShaderLibrary>()) {}
Renderer::~Renderer() = default;

void Renderer::addLayer(std::unique_ptr<Layer> layer) { layers_.push_back(std::move(layer)); }

void Renderer::setScene(const Scene& scene) {
  scene_ = scene;
  for (const auto& layer : layers_) layer->setScene(scene_);
}

void Renderer::setFrame(const Frame& frame) {
  frame_ = frame;
  for (const auto& layer : layers_) layer->setFrame(scene_, frame_);
}

void Renderer::rebuild(Layer& layer) { layer.setFrame(scene_, frame_); }

size_t Renderer::pointsDrawn() const {
  size_t n = 0;
  for (const auto& layer : layers_)
    if (layer->visible) n += layer->pointCount();
  return n;
}

void clearView(int width, int height) {
  glViewport(0, 0, width, height);
  glClearColor(0.08f, 0.09f, 0.11f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void Renderer::draw(const Camera& camera, int width, int height) const {
  clearView(width, height);
  // Layers are composited in order (painter's algorithm): the map lies under the sweep
  // whatever the view, and translucent rasters blend predictably.
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  DrawContext context{camera.viewProjection(), *shaders_, float(height) / 720.0f};
  for (const auto& layer : layers_) {
    if (!layer->visible) continue;
    context.opacity = layer->opacity;
    layer->draw(context);
  }
}

}  // namespace hdprior::render
