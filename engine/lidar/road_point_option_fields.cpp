#include "engine/lidar/sweep_road_points.h"

namespace hdprior {

std::vector<OptionField> optionFields(SweepRoadPointOptions& o) {
  return {
      {"thin_cell", &o.thinCell, "[0, 10]", "m", "road points are thinned to one per cell of this size (0: all)"}};
}

std::vector<OptionField> optionFields(GroundSegmentationOptions& o) {
  return {
      {"min_range", &o.minRange, "[0, 8)", "m", "nearer returns hit the vehicle (below the first zone's 8 m)"},
      {"max_range", &o.maxRange, "(0, 1000]", "m", "farther returns are not segmented"},
      {"seed_height", &o.seedHeight, "(0, 10]", "m", "a bin's plane is fitted to points up to this above its lowest"},
      {"plane_distance", &o.planeDistance, "(0, 10]", "m", "ground: this close to the bin's plane"},
      {"max_tilt_deg", &o.maxTiltDeg, "(0, 90)", "deg", "steeper bin planes are walls, cars, vegetation"},
      {"max_elevation", &o.maxElevation, "[0, 100]", "m", "a bin's plane may lie this far above the expected road level ..."},
      {"elevation_per_metre", &o.elevationPerMetre, "[0, 10]", "m/m", "... plus this per metre of range (slopes)"}};
}

std::vector<OptionField> optionFields(RoadPointOptions& o) {
  return {
      {"max_range", &o.maxRange, "(0, 1000]", "m", "road points farther from the origin are not used"},
      {"max_step", &o.maxStep, "(0, 10]", "m", "height change between neighbouring road points that ends a ring's walk (a kerb) ..."},
      {"step_per_metre", &o.stepPerMetre, "[0, 10]", "m/m", "... plus this per metre between them"},
      {"max_camber", &o.maxCamber, "[0, 0.5]", "m/m", "the road's cross slope up to this is taken out before the step test"},
      {"max_gap", &o.maxGap, "(0, 1000]", "m", "a longer gap along a ring ends its walk"},
      {"window", &o.window, "[0, 1000]", "m", "the step test looks this far back along the walk"},
      {"gutter_rise", &o.gutterRise, "[0, 10]", "m", "a rise this high out of the gutter ends the road without a kerb (0: off)"},
      {"seed_half_width", &o.seedHalfWidth, "(0, 100]", "m", "walks start from ground points this close to the vehicle's axis ..."},
      {"seed_tolerance", &o.seedTolerance, "(0, 10]", "m", "... and this close to the road level"}};
}

}  // namespace hdprior
