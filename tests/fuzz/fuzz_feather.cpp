// Fuzz target: the Arrow IPC (feather) parser and the sweep reader on top of it.
// Any exception other than hdprior::Error, any crash or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/error.h"
#include "engine/io/feather.h"
#include "engine/io/lidar_sweep.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const uint8_t> bytes(data, size);
  try {
    const hdprior::arrow::Table table = hdprior::arrow::parseFeather(bytes, "fuzz.feather");
    for (const hdprior::arrow::Column& c : table.columns) {
      if (c.type == hdprior::arrow::Type::Utf8) {
        for (int64_t i = 0; i < c.length; ++i) (void)c.stringAt(i);
      } else {
        (void)c.toDouble();
      }
    }
    (void)hdprior::parseLidarSweep(bytes, 0, "fuzz.feather");
  } catch (const hdprior::Error&) {
  }
  return 0;
}
