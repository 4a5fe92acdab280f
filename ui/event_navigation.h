#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/pipeline/run_events.h"

namespace hdprior::ui {

// A place the user marked in the log, with a note.
struct Bookmark {
  size_t frame = 0;
  std::string note;
};

// The event N (direction +1) or Shift+N (-1) goes to from the current frame: the next one in that
// direction after `current` (the event last gone to) while the view is still at its frame; else N
// goes to the first event at or after the frame (one here not yet visited counts), Shift+N to the
// last one before it. nullopt: none that way.
std::optional<size_t> stepEvent(const std::vector<RunEvent>& events, std::optional<size_t> current, size_t frame, int direction);

}  // namespace hdprior::ui
