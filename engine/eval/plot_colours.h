#pragma once
#include "engine/eval/rgb_image.h"

namespace hdprior {

// The colours every plot of hdprior draws its axes and labels in.
inline constexpr Rgb kAxisColour{60, 60, 60}, kTextColour{30, 30, 30};

}  // namespace hdprior
