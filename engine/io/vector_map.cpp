#include "engine/io/vector_map.h"

#include <algorithm>

#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"

namespace hdprior {
using namespace json_reading;
using nlohmann::json;

namespace {

Polyline3 readPolyline(const json& arr, const std::string& where, const std::string& source) {
  if (!arr.is_array()) throw Error(source, where + " is not an array of points");
  Polyline3 line;
  line.reserve(arr.size());
  for (size_t i = 0; i < arr.size(); ++i) {
    const std::string w = where + "[" + std::to_string(i) + "]";
    line.emplace_back(number(member(arr[i], "x", w, source), w + ".x", source),
                      number(member(arr[i], "y", w, source), w + ".y", source),
                      number(member(arr[i], "z", w, source), w + ".z", source));
  }
  return line;
}

std::vector<int64_t> readIds(const json& arr, const std::string& where, const std::string& source) {
  if (!arr.is_array()) throw Error(source, where + " is not an array of ids");
  std::vector<int64_t> ids;
  for (const json& v : arr) ids.push_back(integer(v, where, source));
  return ids;
}

std::optional<int64_t> readOptionalId(const json& obj, const char* key, const std::string& where,
                                      const std::string& source) {
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return std::nullopt;
  return integer(*it, where + "." + key, source);
}

std::string readString(const json& obj, const char* key, const std::string& where, const std::string& source) {
  const json& v = member(obj, key, where, source);
  if (!v.is_string()) throw Error(source, where + "." + key + " is not a string");
  return v.get<std::string>();
}

const json& section(const json& root, const char* key, const std::string& source) {
  const json& s = member(root, key, "vector map", source);
  if (!s.is_object()) throw Error(source, std::string("'") + key + "' is not an object keyed by id");
  return s;
}

DrivableArea readDrivableArea(const json& j, const std::string& where, const std::string& source) {
  DrivableArea a;
  a.id = integer(member(j, "id", where, source), where + ".id", source);
  a.areaBoundary = readPolyline(member(j, "area_boundary", where, source), where + ".area_boundary", source);
  if (a.areaBoundary.size() < 3) {
    throw Error(source, where + " has " + std::to_string(a.areaBoundary.size()) +
                            " vertices; a polygon needs at least 3");
  }
  return a;
}

LaneSegment readLaneSegment(const json& j, const std::string& where, const std::string& source) {
  LaneSegment l;
  l.id = integer(member(j, "id", where, source), where + ".id", source);
  const json& inter = member(j, "is_intersection", where, source);
  if (!inter.is_boolean()) throw Error(source, where + ".is_intersection is not a boolean");
  l.isIntersection = inter.get<bool>();
  l.laneType = readString(j, "lane_type", where, source);
  l.leftLaneBoundary = readPolyline(member(j, "left_lane_boundary", where, source), where + ".left_lane_boundary", source);
  l.rightLaneBoundary =
      readPolyline(member(j, "right_lane_boundary", where, source), where + ".right_lane_boundary", source);
  if (l.leftLaneBoundary.size() < 2 || l.rightLaneBoundary.size() < 2) {
    throw Error(source, where + " has a lane boundary with fewer than 2 points");
  }
  l.leftLaneMarkType = readString(j, "left_lane_mark_type", where, source);
  l.rightLaneMarkType = readString(j, "right_lane_mark_type", where, source);
  l.successors = readIds(member(j, "successors", where, source), where + ".successors", source);
  l.predecessors = readIds(member(j, "predecessors", where, source), where + ".predecessors", source);
  l.leftNeighborId = readOptionalId(j, "left_neighbor_id", where, source);
  l.rightNeighborId = readOptionalId(j, "right_neighbor_id", where, source);
  return l;
}

PedestrianCrossing readCrossing(const json& j, const std::string& where, const std::string& source) {
  PedestrianCrossing c;
  c.id = integer(member(j, "id", where, source), where + ".id", source);
  c.edge1 = readPolyline(member(j, "edge1", where, source), where + ".edge1", source);
  c.edge2 = readPolyline(member(j, "edge2", where, source), where + ".edge2", source);
  if (c.edge1.size() != 2 || c.edge2.size() != 2) throw Error(source, where + " edges must have 2 points each");
  return c;
}

template <class T, class ReadFn>
std::vector<T> readSection(const json& root, const char* key, const char* kind, const std::string& source,
                           ReadFn read) {
  std::vector<T> items;
  for (const auto& [id, value] : section(root, key, source).items()) {
    items.push_back(read(value, std::string(kind) + " " + id, source));
  }
  std::sort(items.begin(), items.end(), [](const T& a, const T& b) { return a.id < b.id; });
  return items;
}

json toJson(const Polyline3& line) {
  json arr = json::array();
  for (const Eigen::Vector3d& p : line) arr.push_back({{"x", p.x()}, {"y", p.y()}, {"z", p.z()}});
  return arr;
}

json toJson(const std::optional<int64_t>& id) { return id ? json(*id) : json(nullptr); }

}  // namespace

VectorMap parseVectorMap(const std::string& text, const std::string& source) {
  const json root = parse(text, source);
  VectorMap map;
  map.drivableAreas = readSection<DrivableArea>(root, "drivable_areas", "drivable area", source, readDrivableArea);
  map.laneSegments = readSection<LaneSegment>(root, "lane_segments", "lane segment", source, readLaneSegment);
  map.pedestrianCrossings =
      readSection<PedestrianCrossing>(root, "pedestrian_crossings", "pedestrian crossing", source, readCrossing);
  return map;
}

VectorMap readVectorMap(const std::filesystem::path& path) { return parseVectorMap(readFileText(path), path.string()); }

std::string vectorMapToJson(const VectorMap& map) {
  json root;
  json& areas = root["drivable_areas"] = json::object();
  for (const DrivableArea& a : map.drivableAreas) {
    areas[std::to_string(a.id)] = {{"area_boundary", toJson(a.areaBoundary)}, {"id", a.id}};
  }
  json& lanes = root["lane_segments"] = json::object();
  for (const LaneSegment& l : map.laneSegments) {
    lanes[std::to_string(l.id)] = {{"id", l.id},
                                   {"is_intersection", l.isIntersection},
                                   {"lane_type", l.laneType},
                                   {"left_lane_boundary", toJson(l.leftLaneBoundary)},
                                   {"left_lane_mark_type", l.leftLaneMarkType},
                                   {"right_lane_boundary", toJson(l.rightLaneBoundary)},
                                   {"right_lane_mark_type", l.rightLaneMarkType},
                                   {"successors", l.successors},
                                   {"predecessors", l.predecessors},
                                   {"right_neighbor_id", toJson(l.rightNeighborId)},
                                   {"left_neighbor_id", toJson(l.leftNeighborId)}};
  }
  json& crossings = root["pedestrian_crossings"] = json::object();
  for (const PedestrianCrossing& c : map.pedestrianCrossings) {
    crossings[std::to_string(c.id)] = {{"edge1", toJson(c.edge1)}, {"edge2", toJson(c.edge2)}, {"id", c.id}};
  }
  return root.dump();
}

}  // namespace hdprior
