#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/io/npy.h"
#include "engine/io/sim2.h"
#include "engine/io/vector_map.h"
#include "engine/sim/height_field.h"

namespace hdprior {

// A junction (or bend, degree 2) of a procedural town's street network.
struct TownNode {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  int degree = 0;
};

// A street between two nodes: straight or a quadratic Bezier curve.
struct TownStreet {
  int from = 0, to = 0;
  Eigen::Vector2d control = Eigen::Vector2d::Zero();  // Bezier control point (the midpoint if straight)
  bool curved = false;
  bool corridor = false;  // one of the long loops without junctions
  double width = 0.0;     // metres, kerb to kerb
  int lanesPerDirection = 1;
  double length = 0.0;    // along the curve, node centre to node centre
};

// A procedural town as a full Argoverse 2 map: the vector map, the ground-height raster
// (float16 values, NaN outside the region of interest) with its img_Sim2_city, and the
// street network and terrain it was made from (ground truth for tests and the simulator).
struct TownMap {
  uint64_t seed = 0;
  VectorMap vectorMap;
  NpyArray groundHeight;  // shape {rows, cols}, row 0 at the smallest y
  Sim2 imgSim2City;
  HeightField terrain;
  std::vector<TownNode> nodes;
  std::vector<TownStreet> streets;
};

}  // namespace hdprior
