// Fuzz target: the .npy parser.
#include <cstddef>
#include <cstdint>

#include "engine/error.h"
#include "engine/io/npy.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    (void)hdprior::parseNpy({data, size}, "fuzz.npy");
  } catch (const hdprior::Error&) {
  }
  return 0;
}
