#include <gtest/gtest.h>

#include "ui/event_navigation.h"

namespace hdprior::test {
namespace {

std::vector<RunEvent> eventsAt(std::initializer_list<size_t> frames) {
  std::vector<RunEvent> events;
  for (size_t f : frames) events.push_back({RunEvent::Kind::Rejected, events.size(), f, ""});
  return events;
}

// From the start of a log whose first event is at frame 0, N goes to it, then on through the
// events sharing a frame, and Shift+N comes back; stepping away by hand starts again from the frame.
TEST(EventNavigation, NextAndPreviousFromTheFrameAndTheLastEvent) {
  const std::vector<RunEvent> e = eventsAt({0, 3, 3, 9});
  EXPECT_EQ(ui::stepEvent(e, std::nullopt, 0, 1), std::optional<size_t>(0));
  EXPECT_EQ(ui::stepEvent(e, 0, 0, 1), std::optional<size_t>(1));
  EXPECT_EQ(ui::stepEvent(e, 1, 3, 1), std::optional<size_t>(2));
  EXPECT_EQ(ui::stepEvent(e, 2, 3, -1), std::optional<size_t>(1));
  EXPECT_EQ(ui::stepEvent(e, 3, 9, 1), std::nullopt);
  EXPECT_EQ(ui::stepEvent(e, std::nullopt, 0, -1), std::nullopt);
  EXPECT_EQ(ui::stepEvent(e, 1, 5, 1), std::optional<size_t>(3));   // moved to frame 5 by hand
  EXPECT_EQ(ui::stepEvent(e, 1, 5, -1), std::optional<size_t>(2));
  EXPECT_EQ(ui::stepEvent(eventsAt({}), std::nullopt, 0, 1), std::nullopt);
}

}  // namespace
}  // namespace hdprior::test
