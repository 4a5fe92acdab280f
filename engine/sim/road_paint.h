#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/map/grid_geometry.h"

namespace hdprior {

struct VectorMap;

// Painted road markings (retro-reflective paint, several times as bright as asphalt).
struct PaintOptions {
  double lineWidth = 0.15, doubleLineGap = 0.12;  // lane lines; a double line's two lines apart
  double dashLength = 3.0, dashGap = 9.0;         // dashed lane lines
  double stripeWidth = 0.5, stripeGap = 0.5;      // zebra crossings
  uint8_t white = 60, yellow = 45;                // reflectivity (asphalt 8-18)
  double wear = 0.0;                              // share of 0.25 m cells worn away (asphalt shows)
  uint64_t wearSeed = 0;
  double cellSize = 2.0;                          // of the lookup grid, metres
};

// The markings of a map's lanes (mark types SOLID_WHITE, DASHED_WHITE, DOUBLE_SOLID_YELLOW,
// DASH_SOLID_YELLOW, ...; NONE and UNKNOWN are not painted) and its pedestrian crossings as
// zebra stripes (running across the crossing, edge1 to edge2), within [lo, hi], in a grid of
// cells listing the marks over them.
class RoadPaint {
 public:
  RoadPaint() = default;
  RoadPaint(const VectorMap& map, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const PaintOptions& options = {});
  // The paint's reflectivity at a point on the road; 0 where there is none.
  uint8_t reflectivityAt(const Eigen::Vector2d& city) const;
  size_t markCount() const { return marks_.size(); }

  // A rectangle painted along `along` from `origin` for `length`, across it from acrossMin to
  // acrossMax, in dashes `on` metres long every `period` metres (solid: period 0) from `phase`.
  struct Mark {
    Eigen::Vector2d origin, along;
    double length = 0.0, acrossMin = 0.0, acrossMax = 0.0;
    double phase = 0.0, on = 0.0, period = 0.0;
    uint8_t reflectivity = 0;
  };

 private:
  void index(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);

  PaintOptions options_;
  std::vector<Mark> marks_;
  GridGeometry grid_;
  std::vector<uint32_t> cellStart_, items_;
};

}  // namespace hdprior
