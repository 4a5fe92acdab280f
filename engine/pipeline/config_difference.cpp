#include "engine/pipeline/config_difference.h"

#include <nlohmann/json.hpp>

namespace hdprior {
namespace {

using json = nlohmann::ordered_json;

void compare(const json& a, const json& b, const std::string& key, std::vector<std::string>& out) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [name, value] : a.items())
      if (b.contains(name)) compare(value, b.at(name), key.empty() ? name : key + "." + name, out);
    return;
  }
  if (a != b) out.push_back(key + " " + a.dump() + " -> " + b.dump());
}

}  // namespace

std::vector<std::string> configDifferences(const Config& before, const Config& after) {
  std::vector<std::string> out;
  compare(json::parse(formatConfig(before)), json::parse(formatConfig(after)), "", out);
  return out;
}

}  // namespace hdprior
