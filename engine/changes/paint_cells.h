#pragma once
#include <cstdint>
#include <unordered_map>
#include <utility>

#include <Eigen/Core>

namespace hdprior {

// A square of road near the sensor, over a whole drive.
struct PaintCell {
  int road = 0;  // road points that fell in it
  int runs = 0;  // paint runs centred in it: a cell with one is painted, however many sweeps saw it
  float brightness = 0.0f;  // the road points' summed brightness (SweepPaint::brightness)
  uint8_t place = 0;  // what the map has here, as the check that owns the cells reads it
};

// Road cells seen and those of them painted.
struct PaintTally {
  int road = 0, painted = 0;
  void add(const PaintCell& c) { road += c.road > 0, painted += c.road > 0 && c.runs > 0; }
};

// The log-likelihood ratio of a tally: painted (`contrast` times the asphalt's share of painted
// cells, at least `minShare`) against asphalt, one binomial draw per cell.
double paintEvidence(const PaintTally& t, double asphaltShare, double contrast, double minShare);
// The confidence a verdict drawn from a log-likelihood ratio carries: the logistic of its size.
double evidenceConfidence(double evidence);

// The road near the sensor over a drive, in city cells `size` metres wide. Road marks are fixed in
// the world, so a cell is counted once however many sweeps see it.
class PaintCells {
 public:
  explicit PaintCells(double size) : size_(size) {}

  // The cell at a city point, and whether it is new.
  std::pair<PaintCell&, bool> at(const Eigen::Vector2d& city);
  const PaintCell* find(const Eigen::Vector2d& city) const;
  Eigen::Vector2d centreOf(const Eigen::Vector2d& city) const { return ((city / size_).array().floor() + 0.5) * size_; }
  double size() const { return size_; }

  // visit(centre, cell) for every cell.
  template <typename Visit>
  void forEach(Visit&& visit) const {
    for (const auto& [key, cell] : cells_) visit(Eigen::Vector2d((double(key >> 32) + 0.5) * size_, (double(int32_t(uint32_t(key))) + 0.5) * size_), cell);
  }

 private:
  int64_t keyOf(const Eigen::Vector2d& city) const;

  double size_;
  std::unordered_map<int64_t, PaintCell> cells_;
};

}  // namespace hdprior
