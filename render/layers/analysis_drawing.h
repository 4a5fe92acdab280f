#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// Shapes on the map plane for the analysis layers (scene-local coordinates). GL lines are one
// pixel wide, so lines that must read at a glance are quads `width` metres wide instead.

// Segments both as quads `width` metres across in the plane z = const of their ends (visible when
// zoomed in) and as one-pixel lines (visible when zoomed out).
struct Strokes {
  std::vector<ColoredVertex> quads, lines;  // triangles; GL_LINES pairs
  void segment(const Eigen::Vector3f& a, const Eigen::Vector3f& b, float width, const Eigen::Vector4f& color);
  void polyline(const std::vector<Eigen::Vector3f>& points, float width, const Eigen::Vector4f& color);
};

// The pairs of a GL_LINES draw tracing a closed loop.
void appendLoopLines(std::vector<ColoredVertex>& lines, const std::vector<Eigen::Vector3f>& loop,
                     const Eigen::Vector4f& color);

// Draws consecutive vertex ranges [ends[i - 1], ends[i]) (the first from 0), each tinted by colors[i].
void drawRanges(const DrawContext& context, const GpuMesh& mesh, Primitive primitive, float pointSize, bool roundPoints,
                std::span<const size_t> ends, std::span<const Eigen::Vector4f* const> colors);

// The closed outline (first point repeated last) of the ellipse centre + axes * (cos t, sin t).
std::vector<Eigen::Vector3f> ellipseLoop(const Eigen::Vector3f& centre, const Eigen::Matrix2f& axes, int segments = 40);
// The half-axes (columns) of the 2-sigma ellipse of a 2x2 covariance.
Eigen::Matrix2f twoSigmaAxes(const Eigen::Matrix2d& covariance);

}  // namespace hdprior::render
