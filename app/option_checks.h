#pragma once
#include <functional>
#include <string>

namespace CLI {
class Validator;
}

namespace hdprior::app {

// Checks of an option's text that CLI11 runs while parsing, worded as hdprior words them: a failed
// check becomes the line "option --NAME: PROBLEM" (parse_error_line.h), before any work starts.

// A whole number >= min: "'x' is not an integer", "must not be negative" (min 0), "must be at least N".
CLI::Validator integerAtLeast(long long min);

// A finite real number: "'x' is not a number".
CLI::Validator finiteNumber();

// An image size WIDTHxHEIGHT (render::parseSize).
CLI::Validator imageSize();

// Accepted when `parse` returns; the reason of the hdprior::Error it throws is the problem.
CLI::Validator parsedBy(std::function<void(const std::string&)> parse);

}  // namespace hdprior::app
