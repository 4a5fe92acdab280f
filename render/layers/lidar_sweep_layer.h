#pragma once
#include <memory>

#include "render/gpu_mesh.h"
#include "render/layer.h"

namespace hdprior::render {

// The current lidar sweep in the city frame (ground-truth pose), coloured by height above
// the ground surface under each point (the ego's ground outside the height raster). Uploaded once per frame change.
class LidarSweepLayer : public Layer {
 public:
  static constexpr const char* kName = "sweep";
  std::string name() const override { return kName; }
  void setFrame(const Scene& scene, const Frame& frame) override;
  void draw(const DrawContext& context) const override;

 private:
  std::unique_ptr<GpuMesh> points_;
};

}  // namespace hdprior::render
