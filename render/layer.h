#pragma once
#include <string>

#include <Eigen/Core>

namespace hdprior::render {

struct Scene;
struct Frame;
struct ShaderLibrary;

struct DrawContext {
  Eigen::Matrix4f viewProjection;
  const ShaderLibrary& shaders;
  float pixelScale = 1.0f;  // image height / 720: point sizes scale with it
};

// One drawable thing. GL resources are created in the calls below, with the context current.
// A new layer is one class in render/layers/ plus one line in layer_registry.cpp.
class Layer {
 public:
  virtual ~Layer() = default;
  virtual std::string name() const = 0;
  // Once, for data that does not change between frames (map rasters, lanes, trajectory).
  virtual void setScene(const Scene& scene) {}
  // On every frame change, for per-frame data (the sweep, the ego pose).
  virtual void setFrame(const Scene& scene, const Frame& frame) {}
  virtual void draw(const DrawContext& context) const = 0;
};

}  // namespace hdprior::render
