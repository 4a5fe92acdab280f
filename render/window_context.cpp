#include "render/window_context.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

#include "engine/error.h"
#include "render/framebuffer_readback.h"
#include "render/gl.h"
#include "render/gl_loader.h"

namespace hdprior::render {
namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown error";
}

}  // namespace

WindowContext::WindowContext(int width, int height, const std::string& title) {
  if (!glfwInit()) throw Error("GLFW", "cannot open a window (is there a display? try xvfb-run): " + lastGlfwError());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string reason = lastGlfwError();
    glfwTerminate();
    throw Error("GLFW", "cannot create an OpenGL 3.3 core-profile window: " + reason);
  }
  glfwMakeContextCurrent(window_);
  try {
    loadGlFunctions(glfwGetProcAddress, "GLFW");
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_); }
void WindowContext::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void WindowContext::setSwapInterval(int interval) { glfwSwapInterval(interval); }
void WindowContext::swapBuffers() { glfwSwapBuffers(window_); }

int WindowContext::framebufferWidth() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int WindowContext::framebufferHeight() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

Image WindowContext::readBackBuffer() const {
  glReadBuffer(GL_BACK);
  return readFramebuffer(framebufferWidth(), framebufferHeight());
}

}  // namespace hdprior::render
