#pragma once
#include <array>

#include <Eigen/Core>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

class GpuTexture;

// The two ways layers draw: per-vertex coloured points/lines/triangles, and a texture on a quad.
// Colours are multiplied by `tint` (RGBA) and the alpha by the layer's opacity.
void drawColored(const DrawContext& context, const GpuMesh& mesh, Primitive primitive, float pointSize = 1.0f,
                 bool roundPoints = false, const Eigen::Vector4f& tint = Eigen::Vector4f::Ones(), size_t first = 0,
                 size_t count = 0);
void drawTextured(const DrawContext& context, const GpuMesh& quad, const GpuTexture& texture,
                  const Eigen::Vector4f& tint);

// Lidar points: every context.pointStride-th vertex of the mesh.
void drawLidarPoints(const DrawContext& context, const GpuMesh& mesh, float pointSize);

// A quad (two triangles) from four corners given counter-clockwise starting at uv (0, 0).
std::array<TexturedVertex, 6> texturedQuad(const std::array<Eigen::Vector3f, 4>& corners);

}  // namespace hdprior::render
