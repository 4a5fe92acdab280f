// Fuzz target: the trajectory file parsers (TUM, KITTI, times files, format detection, seconds).
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/error.h"
#include "engine/io/kitti_trajectory.h"
#include "engine/io/seconds_text.h"
#include "engine/io/trajectory_file.h"

namespace {

template <class F>
void guarded(F&& f) {
  try {
    f();
  } catch (const hdprior::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hdprior;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::vector<int64_t> sweeps = {315966265259836000, 315966265360032000, 315966265460032000};
  guarded([&] { (void)parseTrajectoryText(text, TrajectoryFormat::Tum, "fuzz.tum", sweeps); });
  guarded([&] { (void)parseTrajectoryText(text, TrajectoryFormat::Kitti, "fuzz.txt", sweeps); });
  guarded([&] { (void)parseTrajectoryText(text, detectTrajectoryFormat(text, "fuzz.txt"), "fuzz.txt", sweeps); });
  guarded([&] { (void)parseTimes(text, "fuzz.times"); });
  (void)parseSecondsNs(text.substr(0, 64));
  return 0;
}
