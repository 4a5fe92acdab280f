#include "engine/io/text_lines.h"

#include <charconv>

namespace hdprior {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string> splitFields(const std::string& text, size_t begin, size_t end) {
  std::vector<std::string> fields;
  size_t i = begin;
  while (i < end) {
    while (i < end && isSpace(text[i])) ++i;
    const size_t start = i;
    while (i < end && !isSpace(text[i])) ++i;
    if (i > start) fields.emplace_back(text, start, i - start);
  }
  return fields;
}

}  // namespace

std::vector<TextLine> dataLines(const std::string& text) {
  std::vector<TextLine> lines;
  int number = 0;
  for (size_t begin = 0; begin < text.size();) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    ++number;
    std::vector<std::string> fields = splitFields(text, begin, end);
    if (!fields.empty() && fields.front()[0] != '#') lines.push_back({number, std::move(fields)});
    begin = end + 1;
  }
  return lines;
}

std::optional<double> parseNumber(const std::string& field) {
  const char* first = field.data();
  const char* last = field.data() + field.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && *first == '-') return std::nullopt;
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || end != last || first == last) return std::nullopt;
  return value;
}

}  // namespace hdprior
