#include "engine/pipeline/config_difference.h"

#include <nlohmann/json.hpp>

namespace hdprior {
namespace {

using OrderedJson = nlohmann::ordered_json;  // keeps the keys in the file's order

void compare(const OrderedJson& a, const OrderedJson& b, const std::string& key, std::vector<std::string>& out) {
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
  compare(OrderedJson::parse(formatConfig(before)), OrderedJson::parse(formatConfig(after)), "", out);
  return out;
}

}  // namespace hdprior
