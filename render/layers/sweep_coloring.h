#pragma once
#include <optional>
#include <string>
#include <vector>

#include "engine/geom/se3.h"
#include "render/gpu_mesh.h"
#include "render/layer_legend.h"

namespace hdprior {
struct LidarSweep;
}

namespace hdprior::render {

struct Scene;

// How lidar points are coloured (Turbo colour map).
enum class SweepColoring { Height = 0, Intensity = 1, LaserNumber = 2 };
inline const std::vector<std::string>& sweepColoringNames() {
  static const std::vector<std::string> names = {"height above ground", "intensity", "laser number"};
  return names;
}

// The colour range of SweepColoring::Height, metres above the ground surface under a point.
inline constexpr float kSweepHeightLow = -0.5f, kSweepHeightHigh = 4.0f;
// Intensities at or above this get the top colour (most returns are far below 255).
inline constexpr float kSweepIntensityHigh = 100.0f;

// The colour bar of a colouring; none for laser numbers (a colour per ring, not a scale).
std::optional<ColourScale> sweepColourScale(SweepColoring coloring);

// The sweep's points in the scene frame, placed with `cityTEgo`; `egoGroundZ` (city) stands in
// for the ground outside the height raster.
std::vector<ColoredVertex> sweepVertices(const Scene& scene, const LidarSweep& sweep, const SE3& cityTEgo,
                                         double egoGroundZ, SweepColoring coloring);

}  // namespace hdprior::render
