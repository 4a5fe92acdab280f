// Fuzz target: the vector map JSON and the Sim2 JSON parsers.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/error.h"
#include "engine/io/sim2.h"
#include "engine/io/vector_map.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hdprior::parseVectorMap(text, "fuzz.json");
  } catch (const hdprior::Error&) {
  }
  try {
    (void)hdprior::parseSim2(text, "fuzz.json");
  } catch (const hdprior::Error&) {
  }
  return 0;
}
