#pragma once
#include <array>
#include <memory>
#include <optional>

#include "render/gpu_mesh.h"
#include "render/gpu_texture.h"
#include "render/layer.h"

namespace hdprior {
class GroundHeight;
}

namespace hdprior::render {

// The heights (city z, metres) that map to the two ends of the terrain colour ramp: the 2nd and
// 98th percentiles of the raster's valid pixels; none for an all-NaN raster.
struct HeightRange {
  float low = 0, high = 1;
};
std::optional<HeightRange> groundHeightColorRange(const GroundHeight& ground);

// The ground-height raster, colour-mapped (terrain ramp over its 2nd..98th height percentiles) on a
// flat quad under the ego; no-data pixels are transparent.
class GroundHeightLayer : public Layer {
 public:
  static constexpr const char* kName = "ground";
  std::string name() const override { return kName; }
  void setScene(const Scene& scene) override;
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::optional<ColourScale> colourScale() const override;

 private:
  std::unique_ptr<GpuTexture> texture_;
  std::unique_ptr<GpuMesh> quad_;
  std::optional<HeightRange> range_;
  std::array<Eigen::Vector2d, 4> corners_;  // city x, y of the raster corners (uv order)
};

}  // namespace hdprior::render
