#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/option_fields.h"

namespace hdprior {

enum class MatchBackend { Ndt2d, PclNdt };

// How a scan-to-map match is searched for and judged (docs/method.md, Matching; every key in
// docs/config.md).
struct MatchOptions {
  MatchBackend backend = MatchBackend::Ndt2d;

  // --- 2-D NDT (Ndt2d): each point is scored against the 2 x 2 cells nearest to it ---
  // Coarse to fine; the map must carry an NDT grid of each size (HdMapOptions::ndtCellSizes).
  std::vector<double> cellSizes = {4.0, 2.0, 1.0};
  double outlierRatio = 0.55;
  int maxIterations = 25;               // Newton iterations per level
  int maxCoarseStride = 4;              // coarse levels use every (size / finest)^2-th point, at most this (1: all)
  double maxStepCells = 0.5;            // a step moves at most this many cells ...
  double maxStepYawDeg = 2.0;           // ... and turns at most this much
  double maxStepGain = 8.0;             // Newton steps may be lengthened up to this when the score is flatter than its model
  double translationTolerance = 5e-3;   // converged when a step is below these (on the finest grid;
  double yawToleranceDeg = 5e-3;        // a coarser one's grow with its cell size)
  double timeBudgetMs = 100.0;          // the match stops (status Rejected) beyond this

  // --- PCL's 3-D NDT on the same points at z = 0 (PclNdt) ---
  double pclResolution = 1.0;           // voxel size, metres
  double pclStepSize = 0.1;             // More-Thuente maximum step
  double pclEpsilon = 0.01;             // transformation epsilon
  int pclMaxIterations = 35;
  double pclTargetSpacing = 0.2;        // drivable points of the map are thinned to this grid

  // --- Curb refinement (both backends): the curb points seen are put on the drivable boundary,
  // correcting lateral position and yaw only ---
  double curbHuber = 0.15;              // metres
  double curbMaxDistance = 1.0;         // metres from the boundary at the NDT estimate
  int minCurbPoints = 12;               // curbs a match needs for the refinement and the curb evidence

  // --- Covariance and acceptance (both backends) ---
  // Points in one NDT cell are not independent observations: the Laplace information
  // -H / (|d1| d2) is scaled by (distinct cells hit / points).
  double yawLength = 10.0;              // metres; yaw is compared with translation as yaw * yawLength
  // Observability from the drivable boundary: points within boundaryBand of it add their
  // boundary normal's constraint; a direction is observable when its constraint eigenvalue
  // is at least degenerateRatio of the largest and at least minBoundaryPoints (point-equivalents).
  double boundaryBand = 1.0;            // metres
  double degenerateRatio = 0.02;
  double minBoundaryPoints = 20.0;
  double minInformation = 4.0;          // and the NDT information there at least this (sigma <= 0.5 m)
  int minPoints = 200;
  double minInlierRatio = 0.85;         // share of points placed on the drivable area
  // The prediction's (odometry's) uncertainty: the estimate must lie within the gate.
  Eigen::Vector3d predictionSigma = {1.5, 1.5, 4.0};  // x, y metres (vehicle frame), yaw degrees
  double gateChi2 = 11.34;              // 3 degrees of freedom, 99 %

  // --- A stale map (engine/match/stale_regions.h): regions where the map disagrees are left out ---
  double staleRegionSize = 5.0;         // metres, square regions of the key frame
  double staleDistance = 1.5;           // metres outside the drivable area at the prediction, plus ...
  double staleDistancePerMetre = 0.07;  // ... this per metre of range (the prediction's yaw uncertainty) ...
  double staleShare = 0.5;              // ... for more than this share of a region's points

  // --- Honest uncertainty (both backends; engine/match/match_uncertainty.h) ---
  // The Laplace covariance describes the score's curvature at its optimum, not the match's error: on
  // a wide street or junction the points fit anywhere on a plateau. Each direction's sigma is raised
  // to the half-width of the poses the points allow / evidenceKappa, the map's own error is added,
  // and a direction beyond its cap is reported unobservable.
  double evidenceShare = 0.01;          // poses are allowed while at most this share of the points ...
  int evidenceMinPoints = 5;            // ... (at least this many) leave the drivable area
  double evidenceMargin = 0.2;          // metres beyond the boundary before a point counts as off
  double evidenceCurbBand = 0.5;        // curb points (on the boundary at the estimate) count as off beyond this
  double evidenceCurbShare = 0.2;       // share of those that may leave
  int evidenceStride = 4;               // every n-th road point is counted
  double evidenceMaxOffset = 3.2;       // metres searched along and across the heading ...
  double evidenceMaxYawDeg = 6.4;       // ... and in yaw; beyond: unbounded
  double evidenceKappa = 3.0;           // half-width = kappa sigma
  double mapSigma = 0.20;               // metres: the drivable polygon's own error against the kerb
  double mapSigmaYawDeg = 0.20;
  double maxSigmaAlong = 1.5;           // metres; a direction less certain than this is reported unobservable
  double maxSigmaLateral = 0.3;
  double maxSigmaYawDeg = 0.5;
};
std::vector<OptionField> optionFields(MatchOptions& o);  // its configuration keys


}  // namespace hdprior
