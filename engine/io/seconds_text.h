#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace hdprior {

// Decimal seconds as trajectory files write them ("1317384506.123456789", "1.317384506e+09") to
// int64 nanoseconds exactly, without going through a double (which keeps only ~0.1 us of an epoch
// timestamp), rounded to the nearest nanosecond. nullopt for anything else: a sign, other characters,
// no digits, or a value that does not fit.
std::optional<int64_t> parseSecondsNs(const std::string& text);

// "1234.000000005": all nine nanosecond digits, so parseSecondsNs reads it back exactly.
std::string formatSecondsNs(int64_t ns);

}  // namespace hdprior
