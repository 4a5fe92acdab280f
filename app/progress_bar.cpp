#include "app/progress_bar.h"

#include <algorithm>

#include <unistd.h>

namespace hdprior::app {

ProgressBar::ProgressBar(std::string label, std::string unit, std::FILE* out, std::optional<bool> terminal)
    : label_(std::move(label)), unit_(std::move(unit)), out_(out),
      terminal_(terminal.value_or(::isatty(::fileno(out)) == 1)) {}

void ProgressBar::operator()(size_t done, size_t total) {
  if (terminal_) drawBar(done, total);
  else printLine(done, total);
}

void ProgressBar::drawBar(size_t done, size_t total) {
  const int width = 40, filled = int(width * done / std::max<size_t>(total, 1));
  if (filled == last_ && done != total) return;
  last_ = filled;
  std::fprintf(out_, "\r%s [%s%s] %zu/%zu %s", label_.c_str(), std::string(size_t(filled), '#').c_str(),
               std::string(size_t(width - filled), ' ').c_str(), done, total, unit_.c_str());
  if (done == total) std::fprintf(out_, "\n");
  std::fflush(out_);
}

void ProgressBar::printLine(size_t done, size_t total) {
  const int tenth = done >= total ? 10 : int(10 * done / total);
  if (tenth <= last_ || tenth == 0) return;
  last_ = tenth;
  std::fprintf(out_, "%s: %d %% (%zu/%zu %s)\n", label_.c_str(), 10 * tenth, done, total, unit_.c_str());
  std::fflush(out_);
}

}  // namespace hdprior::app
