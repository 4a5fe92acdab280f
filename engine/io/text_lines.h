#pragma once
#include <optional>
#include <string>
#include <vector>

namespace hdprior {

// One data line of a whitespace-separated text file, with its 1-based line number.
struct TextLine {
  int number = 0;
  std::vector<std::string> fields;
};

// The data lines of a text file: blank lines and lines starting with '#' are skipped; "\r\n" endings
// are accepted.
std::vector<TextLine> dataLines(const std::string& text);

// A field as a number (C locale, an optional leading '+'); nullopt when it is not one. "nan" and
// "inf" are numbers here, so the caller can say that a value is not finite rather than not a number.
std::optional<double> parseNumber(const std::string& field);

}  // namespace hdprior
