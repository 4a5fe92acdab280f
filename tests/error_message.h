// What a call throws, for the tests of refused input.
#pragma once
#include <string>

#include "engine/error.h"

namespace hdprior::test {

// The message of the hdprior::Error `f()` throws, or "" when it throws none.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace hdprior::test
