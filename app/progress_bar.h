#pragma once
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace hdprior::app {

// Progress of long work. On a terminal, a bar redrawn in place ("label [####    ] done/total unit")
// only when it changes; anywhere else (a log file, a pipe) one plain line per 10 % ("label: 30 %
// (36/120 unit)"), since a file would collect every carriage-return frame.
class ProgressBar {
 public:
  // terminal: whether `out` is a terminal; by default asked of the stream (isatty).
  explicit ProgressBar(std::string label, std::string unit = "sweeps", std::FILE* out = stderr,
                       std::optional<bool> terminal = std::nullopt);
  void operator()(size_t done, size_t total);

 private:
  void drawBar(size_t done, size_t total);
  void printLine(size_t done, size_t total);

  std::string label_, unit_;
  std::FILE* out_;
  bool terminal_;
  int last_ = -1;  // the last bar width drawn, or the last tenth printed
};

}  // namespace hdprior::app
