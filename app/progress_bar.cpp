#include "app/progress_bar.h"

#include <algorithm>
#include <cstdio>

namespace hdprior::app {

void ProgressBar::operator()(size_t done, size_t total) {
  const int width = 40, filled = int(width * done / std::max<size_t>(total, 1));
  if (filled == last_ && done != total) return;
  last_ = filled;
  std::fprintf(stderr, "\r%s [%s%s] %zu/%zu %s", label_.c_str(), std::string(size_t(filled), '#').c_str(),
               std::string(size_t(width - filled), ' ').c_str(), done, total, unit_.c_str());
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace hdprior::app
