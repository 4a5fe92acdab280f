// Small vector maps with known geometry for the map-layer tests.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <utility>

#include "engine/io/vector_map.h"

namespace hdprior::test {

inline Polyline3 ring(std::initializer_list<std::pair<double, double>> xy, double z = 0.0) {
  Polyline3 r;
  for (const auto& [x, y] : xy) r.emplace_back(x, y, z);
  return r;
}

inline Polyline3 rectangle(double x0, double y0, double x1, double y1) {
  return ring({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

inline VectorMap mapOf(std::initializer_list<Polyline3> polygons) {
  VectorMap map;
  int64_t id = 1;
  for (const Polyline3& p : polygons) map.drivableAreas.push_back({id++, p});
  return map;
}

}  // namespace hdprior::test
