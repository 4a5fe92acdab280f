#include "render/layers/layer_drawing.h"

#include <algorithm>

#include "render/gl.h"
#include "render/gpu_texture.h"
#include "render/shader_program.h"

namespace hdprior::render {

namespace {

Eigen::Vector4f withOpacity(Eigen::Vector4f tint, float opacity) {
  tint.w() *= opacity;
  return tint;
}

}  // namespace

void drawColored(const DrawContext& context, const GpuMesh& mesh, Primitive primitive, float pointSize,
                 bool roundPoints, const Eigen::Vector4f& tint, size_t first, size_t count) {
  const ShaderProgram& program = context.shaders.colored;
  program.use();
  program.set("viewProjection", context.viewProjection);
  program.set("pointSize", pointSize * context.pixelScale);
  program.set("roundPoints", roundPoints ? 1 : 0);
  program.set("tint", withOpacity(tint, context.opacity));
  mesh.draw(primitive, first, count);
}

void drawLidarPoints(const DrawContext& context, const GpuMesh& mesh, float pointSize) {
  const ShaderProgram& program = context.shaders.colored;
  program.use();
  program.set("viewProjection", context.viewProjection);
  program.set("pointSize", pointSize * context.pixelScale);
  program.set("roundPoints", 0);
  program.set("tint", withOpacity(Eigen::Vector4f::Ones(), context.opacity));
  mesh.drawStrided(Primitive::Points, size_t(std::max(1, context.pointStride)));
}

void drawTextured(const DrawContext& context, const GpuMesh& quad, const GpuTexture& texture,
                  const Eigen::Vector4f& tint) {
  const ShaderProgram& program = context.shaders.textured;
  program.use();
  program.set("viewProjection", context.viewProjection);
  program.set("image", 0);
  program.set("tint", withOpacity(tint, context.opacity));
  texture.bind(0);
  quad.draw(Primitive::Triangles);
}

std::array<TexturedVertex, 6> texturedQuad(const std::array<Eigen::Vector3f, 4>& c) {
  const Eigen::Vector2f uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return {TexturedVertex{c[0], uv[0]}, {c[1], uv[1]}, {c[2], uv[2]},
          TexturedVertex{c[0], uv[0]}, {c[2], uv[2]}, {c[3], uv[3]}};
}

}  // namespace hdprior::render
