#pragma once

namespace hdprior {

// How the lidar's ground is compared with the map's drivable area (hdprior changes).
struct ChangeOptions {
  double cell = 0.5;            // metres, of the evidence grid
  double frameSpacing = 2.0;    // metres of travel between the sweeps added
  int surfaceMinPoints = 2;     // ground points a cell needs for a surface
  double sampleSpacing = 1.0;   // metres between the samples of a boundary
  double stretchLength = 10.0;  // metres: a boundary's verdicts are given per stretch this long
  double reach = 6.0;           // metres: each sample looks this far along its normal, both ways
  // A kerb farther than this from the map's boundary contradicts it (the map's error, the poses'
  // error and a cell's width stay below it).
  double tolerance = 1.25;
  // Metres: an edge off the boundary that the lidar saw only from farther away contradicts nothing
  // (the rings are sparse there, and the road walk runs on over flush verges: 16-37 m away on the
  // tuning family's false alarms).
  double edgeRange = 15.0;
  int minSamples = 5;              // a stretch needs this many observed (contradicting) samples for a verdict
  double contradictedShare = 0.4;  // of its observed samples, for the stretch to be contradicted
  // A polygon shifted as a whole (PolygonOffset): one translation this long putting this share of
  // its observed samples within the band of their edges, and moving this many of them by the
  // band or more, of which no more than this share lie within the band of the map's boundary (on
  // the stale tuning families, the shifted and narrowed polygons it finds read 0.92-1.0 and
  // 0-0.12).
  int polygonMinSamples = 10;
  double polygonShift = 1.0;
  double polygonFitBand = 0.5;
  double polygonFitShare = 0.8;
  double polygonMapShare = 0.25;
  double polygonNeighbourhood = 20.0;  // metres: the other polygons' edges that tell a pose error from it
  double seamDepth = 0.5;       // a sample this far inside the union of the polygons is a seam between two
  double missingGap = 1.0;      // road cells this far outside every polygon are candidates of a missing area ...
  double missingMinDepth = 3.0; // ... which must reach this far out ...
  double missingMinArea = 25.0; // ... and cover this many square metres
  // How far off the poses may be, per metre driven from the first (the built-in odometry lost 2-3 %
  // in its worst turns): a sweep whose kerbs line up with the map only under a shift this large
  // is left out as a pose error; a larger shift is a map change.
  double poseErrorPerMetre = 0.03;
  // The road within groundRange (metres) of the sensor lies on the ground-height raster when the
  // pose is right; a sweep whose road stands further off it than groundOffsetLimit (a kerb's
  // height: the built-in odometry's optimised poses stay within 0.21 m on the tuning family) is
  // left out as a pose error.
  double groundRange = 10.0;
  double groundOffsetLimit = 0.25;
  // Road paint (crossings): measured on the real sweeps, it stands out from asphalt only this near the sensor.
  double paintRange = 12.0;
  double paintContrast = 1.7;  // a bright return: this many times the median of its ring's near road
  int paintRunPoints = 3;      // consecutive bright returns of a ring that make a paint run ...
  double paintRunGap = 0.15;   // ... no farther apart than this (metres)
  // Crossings: the road near the sensor in cells this wide (metres); a cell with a paint run in it is painted.
  double paintCell = 0.25;
  // Missing crossings: a painted crossing's share of painted cells against the log's asphalt's
  // (measured on the tuning family: 2-6x; real edge lines cover a fifth of a crossing).
  double crossingContrast = 3.0;
  double crossingPaintShare = 0.1;  // ... and at least this share, on clean asphalt
  // A crossing is painted when the road inside it is brighter than around it by this many times the
  // lift's uncertainty (CrossingBrightness: on the tuning family, painted crossings read up to 5.4,
  // those the world lacks 0.4 or less) ...
  double crossingZ = 3.0;
  // ... and unpainted when it is no brighter than this many times it, and crossingZ times it below
  // the log's painted crossings.
  double crossingAbsentZ = 1.0;
  double crossingDepth = 3.0, crossingWidth = 6.0;  // metres: the band an unmapped crossing is looked for in
  // The log-likelihood ratio an unmapped crossing needs: the band is looked for around every stray
  // run, and a road's own marks cluster (on the tuning family, false bands reach 10).
  double missingCrossingEvidence = 12.0;
  // Paint this near a painted lane boundary is the line's: the poses are off by up to half a
  // metre and a double line is 0.3 m wide.
  double paintLineReach = 1.0;
  // Lane lines: paint on them stands out within this range on the real sweeps.
  double laneRange = 8.0;
  // A painted line's share of painted cells against the asphalt's: a line crosses a fraction of
  // the cells along it and dashes cover a quarter of it (on the tuning family, lines read 1.6-4x).
  double laneLineContrast = 2.0;
  double laneLineEvidence = 2.0;  // log-likelihood ratio of paint, on the line (consistent) or beside it
  double laneLineAsphalt = 1.0;   // ... and of asphalt on the line, for it to be contradicted
};

}  // namespace hdprior
