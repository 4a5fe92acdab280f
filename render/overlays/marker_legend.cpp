#include "render/overlays/marker_legend.h"

#include <algorithm>

namespace hdprior::render {

OverlayBlock markerLegend(const ScreenCanvas& canvas, const std::vector<MarkerKey>& keys) {
  const float u = canvas.unit(), row = canvas.capHeight() + 4 * u, symbol = 12 * u;
  float width = 0;
  for (const MarkerKey& key : keys) width = std::max(width, symbol + canvas.textWidth(key.name));
  OverlayBlock block;
  block.size = {width, row * keys.size() - 4 * u};
  block.draw = [=](ScreenCanvas& c, const Eigen::Vector2f& at) {
    float y = at.y();
    for (const MarkerKey& key : keys) {
      const float middle = y + c.capHeight() / 2;
      c.disc(at.x() + 2.5f * u, middle, 2.5f * u, key.colour);
      c.rect(at.x() + 2.5f * u, middle - u / 2, at.x() + 9 * u, middle + u / 2, key.colour);  // the heading tick
      c.text(at.x() + symbol, y, key.name, kOverlayText);
      y += row;
    }
  };
  return block;
}

}  // namespace hdprior::render
