#include "ui/event_navigation.h"

namespace hdprior::ui {

std::optional<size_t> stepEvent(const std::vector<RunEvent>& events, std::optional<size_t> current, size_t frame, int direction) {
  if (current && *current < events.size() && events[*current].frame == frame) {
    const long long next = (long long)*current + direction;
    if (next >= 0 && next < (long long)events.size()) return size_t(next);
    return std::nullopt;
  }
  if (direction > 0) {
    for (size_t i = 0; i < events.size(); ++i)
      if (events[i].frame >= frame) return i;
  } else {
    for (size_t i = events.size(); i-- > 0;)
      if (events[i].frame < frame) return i;
  }
  return std::nullopt;
}

}  // namespace hdprior::ui
