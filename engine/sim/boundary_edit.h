#pragma once
#include <optional>
#include <vector>

#include "engine/geom/polygon2d.h"

namespace hdprior {

// A side of a polygon: the vertices from one corner to the next, ring indices first..last
// going forwards (wrapping).
struct RingSide {
  size_t first = 0, last = 0;
};

// The sides between corners (vertices turning more than `cornerDegrees`); a ring with fewer
// than three corners is cut into four sides of about equal length.
std::vector<RingSide> ringSides(const Ring2& ring, double cornerDegrees = 40.0);
Ring2 sideVertices(const Ring2& ring, RingSide side);
double polylineLength2(const Ring2& line);

// An edited polygon and the part of its boundary that differs: `stretch` as written,
// `worldStretch` where it was.
struct BoundaryEdit {
  Ring2 ring, stretch, worldStretch;
};

// The whole side moved inwards by `inset` metres (its ends slide along the neighbouring edges).
// nullopt when it cannot be (a neighbouring edge too short, a result that is not simple or
// not smaller).
std::optional<BoundaryEdit> narrowSide(const Ring2& ring, RingSide side, double inset);
// The side's stretch [s0, s0 + length] (metres from its first vertex) moved by `offset` metres
// (positive outwards), tapered to nothing over `taper` at both ends, with vertices every metre
// there. nullopt when the result is not simple.
std::optional<BoundaryEdit> moveKerbStretch(const Ring2& ring, RingSide side, double s0, double length, double offset,
                                            double taper);

}  // namespace hdprior
