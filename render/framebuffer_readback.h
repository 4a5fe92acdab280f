#pragma once
#include "render/image.h"

namespace hdprior::render {

// Waits for drawing to finish and reads the current context's colour buffer (the one
// glReadBuffer names), rows top to bottom.
Image readFramebuffer(int width, int height);

}  // namespace hdprior::render
