#pragma once
#include <memory>

#include "render/image.h"

namespace hdprior::render {

// A headless OpenGL 3.3+ core-profile context (OSMesa, llvmpipe) with a width x height RGBA
// colour buffer; needs no display. Made current on construction. One per thread.
class OffscreenContext {
 public:
  // Throws Error("OSMesa", reason) if no core context can be created or a size is not positive.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  void makeCurrent();
  // Waits for drawing to finish and returns the colour buffer, rows top to bottom.
  Image readPixels() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
  int width_, height_;
};

}  // namespace hdprior::render
