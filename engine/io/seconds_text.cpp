#include "engine/io/seconds_text.h"

#include <cinttypes>
#include <cstdio>
#include <limits>

namespace hdprior {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

struct Decimal {
  std::string digits;     // the mantissa's digits, leading zeros dropped
  long long pointAt = 0;  // the decimal point sits after this many of them (may be negative or beyond)
};

// "[digits][.digits][(e|E)[+|-]digits]" with at least one mantissa digit.
std::optional<Decimal> decimalOf(const std::string& s) {
  Decimal d;
  size_t i = 0;
  bool any = false, seenPoint = false;
  long long beforePoint = 0;
  for (; i < s.size() && (isDigit(s[i]) || (s[i] == '.' && !seenPoint)); ++i) {
    if (s[i] == '.') {
      seenPoint = true;
      continue;
    }
    any = true;
    if (d.digits.empty() && s[i] == '0') {
      if (seenPoint) --d.pointAt;  // a zero after the point and before any other digit
      continue;
    }
    d.digits += s[i];
    if (!seenPoint) ++beforePoint;
    if (d.digits.size() > 64) return std::nullopt;
  }
  if (!any) return std::nullopt;
  d.pointAt += beforePoint;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    const bool negative = i < s.size() && s[i] == '-';
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (i == s.size()) return std::nullopt;
    long long exponent = 0;
    for (; i < s.size() && isDigit(s[i]); ++i) {
      exponent = exponent * 10 + (s[i] - '0');
      if (exponent > 1000) return std::nullopt;
    }
    d.pointAt += negative ? -exponent : exponent;
  }
  if (i != s.size()) return std::nullopt;
  return d;
}

}  // namespace

std::optional<int64_t> parseSecondsNs(const std::string& text) {
  const std::optional<Decimal> d = decimalOf(text);
  if (!d) return std::nullopt;
  // The first `whole` digits are whole nanoseconds; the next one rounds.
  const long long whole = d->pointAt + 9;
  if (whole > 19) return d->digits.empty() ? std::optional<int64_t>(0) : std::nullopt;
  uint64_t ns = 0;
  for (long long k = 0; k < whole; ++k) ns = ns * 10 + uint64_t(k < (long long)d->digits.size() ? d->digits[size_t(k)] - '0' : 0);
  if (whole >= 0 && whole < (long long)d->digits.size() && d->digits[size_t(whole)] >= '5') ++ns;
  if (ns > uint64_t(std::numeric_limits<int64_t>::max())) return std::nullopt;
  return int64_t(ns);
}

std::string formatSecondsNs(int64_t ns) {
  char b[48];
  const char* sign = ns < 0 ? "-" : "";
  const uint64_t a = ns < 0 ? uint64_t(0) - uint64_t(ns) : uint64_t(ns);
  std::snprintf(b, sizeof b, "%s%" PRIu64 ".%09" PRIu64, sign, a / 1000000000u, a % 1000000000u);
  return b;
}

}  // namespace hdprior
