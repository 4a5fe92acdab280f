#include "render/renderer.h"

#include <exception>

#include "render/gl.h"
#include "render/shader_program.h"

namespace hdprior::render {

Renderer::Renderer() : shaders_(std::make_unique<ShaderLibrary>()), overlay_(std::make_unique<ViewOverlayDrawer>()) {}
Renderer::~Renderer() = default;

void Renderer::addLayer(std::unique_ptr<Layer> layer) { layers_.push_back(std::move(layer)); }

namespace {

// FNV-1a over raw bytes.
void mix(uint64_t& hash, const void* data, size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
}

}  // namespace

uint64_t Renderer::viewKey(const Camera& camera) {
  uint64_t hash = 14695981039346656037ull;
  const Eigen::Matrix4f vp = camera.viewProjection();
  mix(hash, vp.data(), sizeof(float) * 16);
  mix(hash, &generation_, sizeof generation_);
  mix(hash, &showOverlay, sizeof showOverlay);
  mix(hash, &insets_, sizeof insets_);
  for (const auto& layer : layers_) {
    mix(hash, &layer->visible, sizeof layer->visible);
    mix(hash, &layer->opacity, sizeof layer->opacity);
    for (const LayerOption& o : layer->options()) {
      if (o.real) mix(hash, o.real, sizeof(float));
      if (o.integer) mix(hash, o.integer, sizeof(int));
      if (o.color) mix(hash, o.color->data(), sizeof(float) * 4);
    }
  }
  return hash;
}

void Renderer::setScene(const Scene& scene) {
  ++generation_;
  scene_ = scene;
  for (const auto& layer : layers_) layer->setScene(scene_);
}

void Renderer::setFrame(const Frame& frame) {
  ++generation_;
  frame_ = frame;
  // One layer's failure (an unreadable neighbouring sweep) leaves the others up to date; the
  // first error is reported once all have run.
  std::exception_ptr first;
  for (const auto& layer : layers_) {
    try {
      layer->setFrame(scene_, frame_);
    } catch (...) {
      if (!first) first = std::current_exception();
    }
  }
  if (first) std::rethrow_exception(first);
}

void Renderer::setAnalysis(Analysis analysis) {
  ++generation_;
  analysis_ = std::move(analysis);
  for (const auto& layer : layers_) layer->setAnalysis(scene_, analysis_);
}

void Renderer::rebuild(Layer& layer) {
  ++generation_;
  layer.setFrame(scene_, frame_);
}

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

void Renderer::draw(const Camera& camera, int width, int height, int pointStride) const {
  clearView(width, height);
  // Layers are composited in order (painter's algorithm): the map lies under the sweep
  // whatever the view, and translucent rasters blend predictably.
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  DrawContext context{camera.viewProjection(), *shaders_, float(height) / 720.0f};
  context.pointStride = pointStride;
  for (const auto& layer : layers_) {
    if (!layer->visible) continue;
    context.opacity = layer->opacity;
    layer->draw(context);
  }
  if (showOverlay) overlay_->draw(viewOverlay(layers_, camera, width, height, insets_), *shaders_);
}

}  // namespace hdprior::render
