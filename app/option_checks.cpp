#include "app/option_checks.h"

#include <CLI/CLI.hpp>
#include <cmath>

#include "engine/error.h"
#include "render/snapshot.h"

namespace hdprior::app {

CLI::Validator integerAtLeast(long long min) {
  return CLI::Validator(
      [min](std::string& text) -> std::string {
        long long n = 0;
        try {
          size_t used = 0;
          n = std::stoll(text, &used);
          if (used != text.size()) return "'" + text + "' is not an integer";
        } catch (const std::exception&) {
          return "'" + text + "' is not an integer";
        }
        if (n >= min) return "";
        return min == 0 ? "must not be negative" : "must be at least " + std::to_string(min);
      },
      "");
}

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          size_t used = 0;
          const double d = std::stod(text, &used);
          if (used == text.size() && std::isfinite(d)) return "";
        } catch (const std::exception&) {
        }
        return "'" + text + "' is not a number";
      },
      "");
}

CLI::Validator parsedBy(std::function<void(const std::string&)> parse) {
  return CLI::Validator(
      [parse = std::move(parse)](std::string& text) -> std::string {
        try {
          parse(text);
          return "";
        } catch (const Error& e) {
          return e.reason();
        }
      },
      "");
}

CLI::Validator imageSize() {
  return parsedBy([](const std::string& text) {
    int width = 0, height = 0;
    render::parseSize(text, width, height);
  });
}

}  // namespace hdprior::app
