#pragma once
// Light helpers to read nlohmann::json strictly; include only from .cpp files.
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/error.h"

namespace hdprior::json_reading {

inline nlohmann::json parse(const std::string& text, const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for number overflow
    throw Error(source, std::string("invalid JSON: ") + e.what());
  }
}

inline const nlohmann::json& member(const nlohmann::json& obj, const char* key, const std::string& where,
                                    const std::string& source) {
  if (!obj.is_object()) throw Error(source, where + " is not an object");
  const auto it = obj.find(key);
  if (it == obj.end()) throw Error(source, where + " has no '" + key + "'");
  return *it;
}

inline double number(const nlohmann::json& v, const std::string& where, const std::string& source) {
  if (!v.is_number()) throw Error(source, where + " is not a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw Error(source, where + " is not finite");
  return d;
}

inline int64_t integer(const nlohmann::json& v, const std::string& where, const std::string& source) {
  if (!v.is_number_integer()) throw Error(source, where + " is not an integer");
  return v.get<int64_t>();
}

}  // namespace hdprior::json_reading
