#pragma once
#include "engine/changes/change_options.h"
#include "engine/changes/surface_evidence.h"

namespace hdprior {

// Sets each cell's Surface from what the road walk made of the ground points seen there: road
// where it reached most of them, not road where it saw them and reached none (it stops at kerbs
// and gutters), unknown where it saw too few. Only the road the vehicle drove along is seen as
// road this way: the walk does not turn into cross streets, so there ground that is not road is
// no evidence by itself (readBoundary asks for a kerb).
void classifySurface(SurfaceEvidence& evidence, const ChangeOptions& options);

}  // namespace hdprior
