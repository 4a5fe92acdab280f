#pragma once
#include "engine/changes/change_options.h"
#include "engine/changes/surface_evidence.h"

namespace hdprior {

// Sets each cell's Surface: from the cells the road walk reached, road grows over neighbouring
// cells of the same surface (ground height within options.surfaceStep, intensity within
// surfaceIntensityShare), so it covers the cross streets the walk never turned into; the cells
// it refused (a kerb, a slope up, a brighter sidewalk or verge) and their surface up to
// options.reach beyond are not road; the rest stays unknown.
void classifySurface(SurfaceEvidence& evidence, const ChangeOptions& options);

}  // namespace hdprior
