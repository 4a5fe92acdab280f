#pragma once
#include <string>
#include <vector>

namespace hdprior {

// One key of the configuration as a user reads it: the reference (docs/config.md, `hdprior config
// --reference`) is made from these, as the loader, `config --check` and `config --defaults` are
// made from the schema behind them (engine/pipeline/config.cpp).
struct ConfigKey {
  std::string key;           // "match.min_points"
  std::string defaultValue;  // as JSON: "200", "[4.0, 2.0, 1.0]", "\"ndt2d\""
  std::string range;         // "[1, 10000000]", "(0, 1)", or the names allowed: "ndt2d | pcl"
  std::string unit;          // "m", "deg", "" (a count or a ratio)
  std::string description;   // one line
};

// Every key, in the order of the reference.
std::vector<ConfigKey> configKeys();

// The configuration reference in Markdown: docs/config.md.
std::string configReference();

}  // namespace hdprior
