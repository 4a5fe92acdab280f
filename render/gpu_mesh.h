#pragma once
#include <cstddef>
#include <span>

#include <Eigen/Core>

namespace hdprior::render {

struct ColoredVertex {
  Eigen::Vector3f position;
  Eigen::Vector4f color;  // RGBA in [0, 1]
};
struct TexturedVertex {
  Eigen::Vector3f position;
  Eigen::Vector2f uv;
};

// Primitive kinds, kept GL-free in headers.
enum class Primitive { Points, Lines, LineStrip, LineLoop, Triangles, TriangleFan };

// A vertex array with one buffer; upload replaces its contents. Needs a current context.
class GpuMesh {
 public:
  GpuMesh();
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  void upload(std::span<const ColoredVertex> vertices);
  void upload(std::span<const TexturedVertex> vertices);
  // Draws vertices [first, first + count) (all when count is 0).
  void draw(Primitive primitive, size_t first = 0, size_t count = 0) const;
  // Draws every `stride`-th vertex (0, stride, 2 stride, ...): a uniform subset of a point cloud.
  void drawStrided(Primitive primitive, size_t stride) const;
  size_t size() const { return count_; }

 private:
  unsigned vao_ = 0, vbo_ = 0;
  size_t count_ = 0;
  mutable unsigned ebo_ = 0;  // indices of drawStrided, built on first use
  mutable size_t eboStride_ = 0, eboCount_ = 0;
};

}  // namespace hdprior::render
