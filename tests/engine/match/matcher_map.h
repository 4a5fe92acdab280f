// The HD map of a synthetic vector map with the NDT grids the matcher's defaults name.
#pragma once
#include <optional>
#include <utility>

#include "engine/io/vector_map.h"
#include "engine/map/hd_map.h"
#include "engine/match/match_options.h"

namespace hdprior::test {

inline HdMap matcherMap(VectorMap vm) {
  HdMapOptions o;
  o.ndtCellSizes = MatchOptions{}.cellSizes;
  return HdMap::build(std::move(vm), std::nullopt, o, "synthetic");
}

}  // namespace hdprior::test
