#include "render/gpu_mesh.h"

#include <cstdint>
#include <vector>

#include "render/gl.h"

namespace hdprior::render {
namespace {

GLenum glPrimitive(Primitive p) {
  switch (p) {
    case Primitive::Points: return GL_POINTS;
    case Primitive::Lines: return GL_LINES;
    case Primitive::LineStrip: return GL_LINE_STRIP;
    case Primitive::LineLoop: return GL_LINE_LOOP;
    case Primitive::Triangles: return GL_TRIANGLES;
    case Primitive::TriangleFan: return GL_TRIANGLE_FAN;
  }
  return GL_POINTS;
}

void attribute(GLuint index, int components, size_t stride, size_t offset) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, GLsizei(stride),
                        reinterpret_cast<const void*>(uintptr_t(offset)));
}

}  // namespace

GpuMesh::GpuMesh() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
}

GpuMesh::~GpuMesh() {
  if (ebo_) glDeleteBuffers(1, &ebo_);
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::upload(std::span<const ColoredVertex> vertices) {
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size_bytes()), vertices.data(), GL_DYNAMIC_DRAW);
  attribute(0, 3, sizeof(ColoredVertex), offsetof(ColoredVertex, position));
  attribute(1, 4, sizeof(ColoredVertex), offsetof(ColoredVertex, color));
  count_ = vertices.size();
}

void GpuMesh::upload(std::span<const TexturedVertex> vertices) {
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size_bytes()), vertices.data(), GL_DYNAMIC_DRAW);
  attribute(0, 3, sizeof(TexturedVertex), offsetof(TexturedVertex, position));
  attribute(1, 2, sizeof(TexturedVertex), offsetof(TexturedVertex, uv));
  count_ = vertices.size();
}

void GpuMesh::drawStrided(Primitive primitive, size_t stride) const {
  if (stride <= 1) return draw(primitive);
  const size_t n = (count_ + stride - 1) / stride;
  if (n == 0) return;
  glBindVertexArray(vao_);
  if (!ebo_) glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);  // recorded in the vertex array
  if (eboStride_ != stride || eboCount_ != count_) {
    std::vector<uint32_t> indices(n);
    for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i * stride);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(n * sizeof(uint32_t)), indices.data(), GL_STATIC_DRAW);
    eboStride_ = stride;
    eboCount_ = count_;
  }
  glDrawElements(glPrimitive(primitive), GLsizei(n), GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::draw(Primitive primitive, size_t first, size_t count) const {
  if (count == 0) count = count_ - first;
  if (first >= count_ || count == 0) return;
  glBindVertexArray(vao_);
  glDrawArrays(glPrimitive(primitive), GLint(first), GLsizei(count));
}

}  // namespace hdprior::render
