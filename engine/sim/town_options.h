#pragma once
#include <cstdint>

namespace hdprior {

// The knobs of a procedural town (engine/sim/town_generator.h). Defaults give a town of
// about 1.4 km x 1.4 km: a jittered 5 x 5 grid of junctions 250 m apart, two corridor loops.
struct TownOptions {
  int gridCols = 5, gridRows = 5;     // junctions of the street grid
  double blockSize = 250.0;           // metres between grid lines
  double jitter = 20.0;               // junctions move up to this far from the grid, metres
  double removedEdgeFraction = 0.2;   // of the inner streets, removed where that leaves T junctions
  double curvedEdgeFraction = 0.3;    // of the streets, bent as quadratic Bezier curves
  double minRoadWidth = 6.0, maxRoadWidth = 20.0;  // metres, one width per street line
  double twoLaneWidth = 11.0;         // from this road width on, two lanes per direction
  double threeLaneWidth = 1e9;        // from this road width on, three (default: never)
  double junctionMargin = 4.0;        // a road ends 1.2 x the widest crossing half width + this from a junction's centre
  int corridors = 2;                  // long loops without junctions on the east and north sides
  double corridorLength = 420.0;      // metres from the grid to the far side of a corridor loop
  double hillGrade = 0.08;            // steepest grade of the terrain anywhere in the town
  double groundResolution = 0.3;      // metres per ground-height pixel
  double groundRadius = 5.0;          // ground height is given within this distance of the road
};

}  // namespace hdprior
