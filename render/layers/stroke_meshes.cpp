#include "render/layers/stroke_meshes.h"

#include "render/layers/layer_drawing.h"

namespace hdprior::render {

void StrokeMeshes::upload(const Strokes& strokes, const std::vector<ColoredVertex>& dots) {
  if (!quads_) {
    quads_ = std::make_unique<GpuMesh>();
    lines_ = std::make_unique<GpuMesh>();
    dots_ = std::make_unique<GpuMesh>();
  }
  quads_->upload(std::span<const ColoredVertex>(strokes.quads));
  lines_->upload(std::span<const ColoredVertex>(strokes.lines));
  dots_->upload(std::span<const ColoredVertex>(dots));
}

void StrokeMeshes::draw(const DrawContext& context, float dotSize) const {
  if (!quads_) return;
  if (quads_->size() > 0) drawColored(context, *quads_, Primitive::Triangles);
  if (lines_->size() > 0) drawColored(context, *lines_, Primitive::Lines);
  if (dots_->size() > 0) drawColored(context, *dots_, Primitive::Points, dotSize, true);
}

}  // namespace hdprior::render
