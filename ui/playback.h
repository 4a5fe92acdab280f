#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hdprior::ui {

// Timeline playback: real time (1x, 2x, 5x the log's sweep timestamps) or one frame per drawn
// frame (max). Stops at the last frame.
struct Playback {
  static constexpr std::array<const char*, 4> kSpeedNames = {"1x", "2x", "5x", "max"};
  static constexpr std::array<double, 4> kSpeeds = {1.0, 2.0, 5.0, 0.0};  // 0: max

  bool playing = false;
  int speed = 0;       // index into kSpeeds
  double clock = 0.0;  // log seconds elapsed since the current frame's timestamp

  void toggle() {
    playing = !playing;
    clock = 0.0;
  }
  // The frame to show after `dt` wall-clock seconds at `frame`.
  size_t advance(size_t frame, const std::vector<int64_t>& timestamps, double dt);
};

}  // namespace hdprior::ui
