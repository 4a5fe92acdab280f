#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hdprior::render {

// One control a layer offers the user, described without any UI toolkit: the app's layers
// panel draws it. The pointer is to the layer's own member. `rebuilds`: a change needs the
// layer's per-frame data built again (Renderer::rebuild), e.g. the colouring of a sweep.
struct LayerOption {
  enum class Kind { Slider, IntSlider, Choice, Color };
  Kind kind = Kind::Slider;
  std::string label;
  float* real = nullptr;
  int* integer = nullptr;
  Eigen::Vector4f* color = nullptr;  // RGBA in [0, 1]
  float min = 0.0f, max = 1.0f;
  std::vector<std::string> choices;
  bool rebuilds = false;

  static LayerOption slider(std::string label, float* value, float min, float max) {
    return {Kind::Slider, std::move(label), value, nullptr, nullptr, min, max, {}, false};
  }
  static LayerOption intSlider(std::string label, int* value, int min, int max, bool rebuilds) {
    return {Kind::IntSlider, std::move(label), nullptr, value, nullptr, float(min), float(max), {}, rebuilds};
  }
  static LayerOption choice(std::string label, int* value, std::vector<std::string> choices, bool rebuilds) {
    return {Kind::Choice, std::move(label), nullptr, value, nullptr, 0, 0, std::move(choices), rebuilds};
  }
  static LayerOption colorPicker(std::string label, Eigen::Vector4f* value) {
    return {Kind::Color, std::move(label), nullptr, nullptr, value, 0, 1, {}, false};
  }
};

}  // namespace hdprior::render
