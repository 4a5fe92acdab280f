#pragma once
#include "engine/pipeline/constraint_colour.h"

namespace hdprior::render {

// The keyframes' status colours, as the engine defines them (engine/pipeline/constraint_colour.h,
// also used by `hdprior plot`), under the renderer's names.
using hdprior::ConstraintClass;
using hdprior::constraintClass;
using hdprior::constraintColour;
using hdprior::kConstraintClasses;
using hdprior::kConstraintClassNames;

}  // namespace hdprior::render
