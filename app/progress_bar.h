#pragma once
#include <cstddef>
#include <string>

namespace hdprior::app {

// A progress bar on stderr ("label [####    ] done/total unit"), redrawn only when it changes.
class ProgressBar {
 public:
  explicit ProgressBar(std::string label, std::string unit = "sweeps") : label_(std::move(label)), unit_(std::move(unit)) {}
  void operator()(size_t done, size_t total);

 private:
  std::string label_, unit_;
  int last_ = -1;
};

}  // namespace hdprior::app
