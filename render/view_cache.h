#pragma once
#include <cstdint>
#include <functional>

namespace hdprior::render {

// The last drawn 3-D view, kept in an offscreen colour + depth buffer. When nothing the view
// depends on changed (same key: camera, frame, layer settings, size), a frame copies it to the
// window instead of drawing every layer again, so panels stay fluid over a heavy scene.
// Needs a current context; create, use and destroy it with the same one.
class ViewCache {
 public:
  ViewCache() = default;
  ~ViewCache();
  ViewCache(const ViewCache&) = delete;
  ViewCache& operator=(const ViewCache&) = delete;

  // Runs `draw` into the cache if `key` or the size changed, then copies the cache into the
  // default framebuffer. Returns true when it drew.
  bool present(uint64_t key, int width, int height, const std::function<void()>& draw);

 private:
  void resize(int width, int height);
  unsigned framebuffer_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
  uint64_t key_ = 0;
  bool valid_ = false;
};

}  // namespace hdprior::render
