#pragma once
#include <cmath>
#include <cstddef>

namespace hdprior {

// A map check scored against the labels of a simulated log, per element of one kind: a report is
// a contradicted drivable area (where its contradicted stretches lie) or a missing surface (its
// outline); or a contradicted or missing crossing (its outline); or a lane line with contradicted
// stretches (where they lie).
struct ChangeScore {
  size_t reports = 0, reportsNearChange = 0;  // reports; those within `match` metres of a labelled change
  size_t changes = 0, changesFound = 0;       // labelled changes the drive passes within `nearRoute` of; those a report lies within `match` of
  double drivenKm = 0.0;

  double precision() const { return reports ? double(reportsNearChange) / double(reports) : NAN; }
  double recall() const { return changes ? double(changesFound) / double(changes) : NAN; }
  size_t falseAlarms() const { return reports - reportsNearChange; }
  ChangeScore& operator+=(const ChangeScore& o);
};

}  // namespace hdprior
