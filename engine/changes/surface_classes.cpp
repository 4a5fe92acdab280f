#include "engine/changes/surface_classes.h"

namespace hdprior {

void classifySurface(SurfaceEvidence& evidence, const ChangeOptions& options) {
  std::vector<Surface> surfaces(evidence.cells().size(), Surface::Unknown);
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const SurfaceCell& c = evidence.cells()[i];
    if (c.road + c.offRoad < options.surfaceMinPoints) continue;
    if (c.road >= options.surfaceMinPoints && c.road >= 2 * c.offRoad) surfaces[i] = Surface::Road;
    else if (4 * c.road < c.offRoad) surfaces[i] = Surface::NotRoad;
  }
  evidence.setSurfaces(std::move(surfaces));
}

}  // namespace hdprior
