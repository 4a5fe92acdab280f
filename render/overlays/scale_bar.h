#pragma once
#include <string>

#include "render/overlays/overlay_block.h"

namespace hdprior::render {

// The longest round length (1, 2 or 5 times a power of ten, in metres) whose bar is at most
// `maxPixels` long at `metresPerPixel`, so the bar reads right at any zoom.
double scaleBarLength(double metresPerPixel, double maxPixels);
// "20 m", "0.5 m".
std::string scaleBarLabel(double metres);

// A white bar with end ticks, `scaleBarLength(metresPerPixel, maxPixels)` long, its length above it.
OverlayBlock scaleBar(const ScreenCanvas& canvas, double metresPerPixel, double maxPixels);

}  // namespace hdprior::render
