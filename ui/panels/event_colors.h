#pragma once
#include <imgui.h>

#include "engine/pipeline/run_events.h"

namespace hdprior::ui {

// One colour per kind of event, shared by the events list and the timeline's ticks.
ImVec4 eventColor(RunEvent::Kind kind);

}  // namespace hdprior::ui
