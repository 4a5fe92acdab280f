#pragma once
#include <string>

#include "render/image.h"

struct GLFWwindow;

namespace hdprior::render {

// A GLFW window with an OpenGL 3.3 core-profile context (GLX; under Xvfb it is llvmpipe),
// made current and with the renderer's GL functions loaded on construction. One per process.
class WindowContext {
 public:
  // Throws Error("GLFW", reason) when there is no display or no 3.3 core context.
  WindowContext(int width, int height, const std::string& title);
  ~WindowContext();
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool shouldClose() const;
  void requestClose();
  // 1: wait for vertical blank (the app), 0: as fast as possible (benchmarks).
  void setSwapInterval(int interval);
  void swapBuffers();
  // The framebuffer size in pixels (can differ from the window size on HiDPI screens).
  int framebufferWidth() const;
  int framebufferHeight() const;
  // The back buffer as drawn so far this frame (call before swapBuffers), rows top to bottom.
  Image readBackBuffer() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace hdprior::render
