#pragma once
#include <vector>

#include "render/layer_legend.h"
#include "render/overlays/overlay_block.h"

namespace hdprior::render {

// One row per marker: its symbol as the map shows it (a dot with a heading tick) and its name.
OverlayBlock markerLegend(const ScreenCanvas& canvas, const std::vector<MarkerKey>& keys);

}  // namespace hdprior::render
