#include "ui/playback.h"

namespace hdprior::ui {

size_t Playback::advance(size_t frame, const std::vector<int64_t>& timestamps, double dt) {
  if (!playing || timestamps.empty()) return frame;
  if (frame + 1 >= timestamps.size()) {
    playing = false;
    return timestamps.size() - 1;
  }
  if (kSpeeds[speed] == 0.0) return frame + 1;
  clock += dt * kSpeeds[speed];
  while (frame + 1 < timestamps.size()) {
    const double gap = double(timestamps[frame + 1] - timestamps[frame]) * 1e-9;
    if (clock < gap) break;
    clock -= gap;
    ++frame;
  }
  return frame;
}

}  // namespace hdprior::ui
