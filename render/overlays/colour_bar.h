#pragma once
#include <string>

#include "render/layer_legend.h"
#include "render/overlays/overlay_block.h"

namespace hdprior::render {

// A colour scale as a horizontal bar: its title above, the colour map from low (left) to high
// (right), and the two end values with their unit under the ends.
OverlayBlock colourBar(const ScreenCanvas& canvas, const ColourScale& scale);

// An end value as the bar prints it: whole numbers from 100 on, else three significant digits;
// then the unit, if any ("-0.5 m", "1234").
std::string colourBarLabel(double value, const std::string& unit);

}  // namespace hdprior::render
