#pragma once
#include <memory>
#include <vector>

#include "render/gpu_mesh.h"
#include "render/layer.h"
#include "render/layers/analysis_drawing.h"

namespace hdprior::render {

// Strokes (quads and one-pixel lines) and round dots on the GPU, drawn in that order: what the
// match and measure layers draw. Created on the first upload (the context must be current).
class StrokeMeshes {
 public:
  void upload(const Strokes& strokes, const std::vector<ColoredVertex>& dots);
  void draw(const DrawContext& context, float dotSize) const;

 private:
  std::unique_ptr<GpuMesh> quads_, lines_, dots_;
};

}  // namespace hdprior::render
