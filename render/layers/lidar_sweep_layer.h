#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The current lidar sweep in the city frame (ground-truth pose), coloured by height above the
// ground surface under each point (the ego's ground outside the height raster), by intensity
// or by laser number. Uploaded once per frame change.
class LidarSweepLayer : public Layer {
 public:
  static constexpr const char* kName = "sweep";
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;
  std::vector<LayerOption> options() override;
  std::optional<ColourScale> colourScale() const override;
  size_t pointCount() const override { return points_ ? points_->size() : 0; }

 private:
  std::unique_ptr<GpuMesh> points_;
  int coloring_ = 0;  // SweepColoring
  float pointSize_ = 2.0f;
};

}  // namespace hdprior::render
