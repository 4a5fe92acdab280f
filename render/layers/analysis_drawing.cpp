#include "render/layers/analysis_drawing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "render/layers/layer_drawing.h"

namespace hdprior::render {

void Strokes::segment(const Eigen::Vector3f& a, const Eigen::Vector3f& b, float width, const Eigen::Vector4f& color) {
  const Eigen::Vector2f d = (b - a).head<2>();
  if (d.norm() < 1e-6f) return;
  lines.push_back({a, color});
  lines.push_back({b, color});
  const Eigen::Vector2f n2 = Eigen::Vector2f(-d.y(), d.x()).normalized() * (0.5f * width);
  const Eigen::Vector3f n(n2.x(), n2.y(), 0.0f);
  const Eigen::Vector3f a0 = a - n, a1 = a + n, b0 = b - n, b1 = b + n;
  for (const Eigen::Vector3f* p : {&a0, &b0, &b1, &a0, &b1, &a1}) quads.push_back({*p, color});
}

void Strokes::polyline(const std::vector<Eigen::Vector3f>& points, float width, const Eigen::Vector4f& color) {
  for (size_t i = 1; i < points.size(); ++i) segment(points[i - 1], points[i], width, color);
}

void appendLoopLines(std::vector<ColoredVertex>& lines, const std::vector<Eigen::Vector3f>& loop,
                     const Eigen::Vector4f& color) {
  for (size_t i = 1; i < loop.size(); ++i) {
    lines.push_back({loop[i - 1], color});
    lines.push_back({loop[i], color});
  }
}

void drawRanges(const DrawContext& context, const GpuMesh& mesh, Primitive primitive, float pointSize, bool roundPoints,
                std::span<const size_t> ends, std::span<const Eigen::Vector4f* const> colors) {
  for (size_t i = 0, first = 0; i < ends.size(); first = ends[i++])
    if (ends[i] > first) drawColored(context, mesh, primitive, pointSize, roundPoints, *colors[i], first, ends[i] - first);
}

std::vector<Eigen::Vector3f> ellipseLoop(const Eigen::Vector3f& centre, const Eigen::Matrix2f& axes, int segments) {
  std::vector<Eigen::Vector3f> loop;
  for (int i = 0; i <= segments; ++i) {
    const float t = 2.0f * std::numbers::pi_v<float> * float(i % segments) / float(segments);
    const Eigen::Vector2f p = axes * Eigen::Vector2f(std::cos(t), std::sin(t));
    loop.push_back(centre + Eigen::Vector3f(p.x(), p.y(), 0.0f));
  }
  return loop;
}

Eigen::Matrix2f twoSigmaAxes(const Eigen::Matrix2d& covariance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (covariance + covariance.transpose()));
  const Eigen::Vector2d sigma = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return (eig.eigenvectors() * (2.0 * sigma).asDiagonal()).cast<float>();
}

}  // namespace hdprior::render
