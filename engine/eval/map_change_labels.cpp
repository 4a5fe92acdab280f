#include "engine/eval/map_change_labels.h"

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/io/file_bytes.h"

namespace hdprior {

namespace {

using nlohmann::json;

std::vector<Eigen::Vector2d> points(const json& list, const std::string& what, const std::string& source) {
  if (!list.is_array()) throw Error(source, what + " is not a list of [x, y] pairs");
  std::vector<Eigen::Vector2d> out;
  for (const json& p : list) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      throw Error(source, what + " has an entry that is not an [x, y] pair");
    out.emplace_back(p[0].get<double>(), p[1].get<double>());
  }
  return out;
}

MapChangeLabel label(const json& c, size_t index, const std::string& source) {
  const std::string at = "change " + std::to_string(index);
  for (const char* key : {"element", "change", "id", "route_distance_m"})
    if (!c.contains(key)) throw Error(source, at + " has no " + key);
  if (!c["element"].is_string() || !c["change"].is_string() || !c["id"].is_number_integer() || !c["route_distance_m"].is_number())
    throw Error(source, at + " has a member of the wrong type");
  MapChangeLabel l{c["element"].get<std::string>(), c["change"].get<std::string>(), c["id"].get<int64_t>(), {},
                   c["route_distance_m"].get<double>()};
  if (c.contains("changed_stretch")) {
    l.places.push_back(points(c["changed_stretch"], at + " changed_stretch", source));
  } else {
    for (const char* key : {"world_outline", "map_outline"})
      if (c.contains(key)) l.places.push_back(points(c[key], at + " " + key, source));
  }
  if (l.places.empty()) throw Error(source, at + " says nowhere where it lies (no outline nor changed_stretch)");
  return l;
}

}  // namespace

std::vector<MapChangeLabel> parseMapChangeLabels(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception&) {
    throw Error(source, "is not valid JSON");
  }
  if (!j.is_object() || !j.contains("changes") || !j["changes"].is_array()) throw Error(source, "has no list 'changes'");
  std::vector<MapChangeLabel> out;
  for (size_t i = 0; i < j["changes"].size(); ++i) out.push_back(label(j["changes"][i], i, source));
  return out;
}

std::vector<MapChangeLabel> readMapChangeLabels(const std::filesystem::path& file) {
  return parseMapChangeLabels(readFileText(file), file.string());
}

std::optional<std::vector<MapChangeLabel>> logMapChangeLabels(const std::filesystem::path& logDir) {
  const std::filesystem::path file = logDir / "map_change.json";
  if (!std::filesystem::exists(file)) return std::nullopt;
  return readMapChangeLabels(file);
}

}  // namespace hdprior
