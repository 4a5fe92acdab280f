#include "ui/panels/event_colors.h"

namespace hdprior::ui {

ImVec4 eventColor(RunEvent::Kind kind) {
  switch (kind) {
    case RunEvent::Kind::Rejected: return ImVec4(0.95f, 0.35f, 0.3f, 1.0f);
    case RunEvent::Kind::Gated: return ImVec4(1.0f, 0.85f, 0.15f, 1.0f);
    case RunEvent::Kind::ConstraintChange: return ImVec4(0.3f, 0.65f, 1.0f, 1.0f);
    case RunEvent::Kind::Beyond3Sigma: return ImVec4(1.0f, 0.5f, 0.9f, 1.0f);
    case RunEvent::Kind::MapChange: return ImVec4(1.0f, 0.3f, 1.0f, 1.0f);
    case RunEvent::Kind::MissedChange: return ImVec4(0.1f, 0.95f, 0.95f, 1.0f);  // the changes layer's labelled cyan
    case RunEvent::Kind::MisalignedSweeps: return ImVec4(1.0f, 0.6f, 0.2f, 1.0f);
    case RunEvent::Kind::SkippedSweep: break;
  }
  return ImVec4(0.7f, 0.7f, 0.7f, 1.0f);
}

}  // namespace hdprior::ui
