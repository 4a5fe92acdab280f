#include "app/parse_error_line.h"

#include <CLI/CLI.hpp>
#include <regex>

namespace hdprior::app {
namespace {

// "--out" names an option, "LOG" a positional argument.
std::string subject(const std::string& name) { return (name.rfind('-', 0) == 0 ? "option " : "argument ") + name; }

// CLI11 lists the unexpected arguments, the first one first.
std::string unexpected(const std::string& list) {
  const std::string first = list.substr(0, list.find(' '));
  const std::string rest = first.size() < list.size() ? " (also: " + list.substr(first.size() + 1) + ")" : "";
  if (first.rfind('-', 0) == 0) return "option " + first.substr(0, first.find('=')) + ": unknown option" + rest;
  return "argument '" + first + "': not expected (too many arguments)" + rest;
}

}  // namespace

std::string parseErrorLine(const CLI::ParseError& error) {
  const std::string message = error.what();
  std::smatch m;
  if (dynamic_cast<const CLI::RequiredError*>(&error) && std::regex_match(message, m, std::regex("(\\S+) is required"))) {
    return subject(m[1]) + ": is required";
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) &&
      std::regex_match(message, m, std::regex("(-\\S+): \\d+ required .* missing"))) {
    return "option " + m[1].str() + ": needs a value";
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error) &&
      std::regex_match(message, m, std::regex("The following arguments? (?:was|were) not expected: (.*)"))) {
    return unexpected(m[1]);
  }
  if (std::regex_match(message, m, std::regex("(-\\S+) requires (\\S+)"))) return "option " + m[1].str() + ": needs " + m[2].str();
  if (std::regex_match(message, m, std::regex("(-\\S+) excludes (\\S+)"))) {
    return "option " + m[1].str() + ": cannot be combined with " + m[2].str();
  }
  if (dynamic_cast<const CLI::ValidationError*>(&error) && std::regex_match(message, m, std::regex("(\\S+): (.*)"))) {
    return subject(m[1]) + ": " + m[2].str();
  }
  return message;
}

}  // namespace hdprior::app
