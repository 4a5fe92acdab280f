#include "engine/map/ndt_grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Eigenvalues>

#include "engine/error.h"
#include "engine/map/drivable_raster.h"

namespace hdprior {
namespace {

// Sums over the drivable cell centres of one NDT cell, in coordinates local to the NDT
// cell's corner (small numbers, so no cancellation in the covariance).
struct Moments {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
};

int floorDiv(long long a, long long b) { return int(a >= 0 ? a / b : -((-a + b - 1) / b)); }

// Regularise the eigenvalues and fill covariance and information.
void finishCell(const Moments& m, const Eigen::Vector2d& corner, double resolution, double minEigenRatio,
                NdtCell& cell) {
  const Eigen::Vector2d mean(m.sx / m.n, m.sy / m.n);
  Eigen::Matrix2d cov;
  cov << m.sxx / m.n - mean.x() * mean.x(), m.sxy / m.n - mean.x() * mean.y(),  //
      m.sxy / m.n - mean.x() * mean.y(), m.syy / m.n - mean.y() * mean.y();
  cov.diagonal().array() += resolution * resolution / 12.0;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig;
  eig.computeDirect(cov);
  Eigen::Vector2d lambda = eig.eigenvalues();  // ascending
  lambda(0) = std::max(lambda(0), minEigenRatio * lambda(1));
  const Eigen::Matrix2d& V = eig.eigenvectors();
  cell.mean = corner + mean;
  cell.covariance = V * lambda.asDiagonal() * V.transpose();
  cell.information = V * lambda.cwiseInverse().asDiagonal() * V.transpose();
  cell.count = int(m.n);
}

// Adds the drivable cells of one raster run (row-local y) to the NDT cells it crosses, in
// closed form: n evenly spaced centres with mean x have sum of squares n (x^2 + res^2 (n^2 - 1) / 12).
void addRun(const DrivableRaster::Run& run, double y, double res, int m, int offX, std::vector<Moments>& row) {
  for (int a = run.begin; a < run.end;) {
    const int ndtCol = (a + offX) / m;
    const int b = std::min(run.end, (ndtCol + 1) * m - offX);
    const double n = b - a;
    const double meanX = ((a + offX) - ndtCol * m + 0.5 * n) * res;
    Moments& mo = row[size_t(ndtCol)];
    mo.n += n;
    mo.sx += n * meanX;
    mo.sy += n * y;
    mo.sxx += n * (meanX * meanX + res * res * (n * n - 1.0) / 12.0);
    mo.sxy += n * meanX * y;
    mo.syy += n * y * y;
    a = b;
  }
}

}  // namespace

NdtGrid NdtGrid::build(const DrivableRaster& raster, const NdtGridOptions& options) {
  const GridGeometry& rg = raster.geometry();
  const double res = rg.resolution;
  const double ratio = options.cellSize / res;
  const long long m = std::llround(ratio);
  if (!std::isfinite(ratio) || m < 1 || std::abs(ratio - double(m)) > 1e-6 * ratio) {
    throw Error("NDT grid", "cell size " + std::to_string(options.cellSize) +
                                " m is not a whole multiple of the raster resolution " + std::to_string(res) + " m");
  }
  if (m * m < options.minPoints) {
    throw Error("NDT grid", "a " + std::to_string(options.cellSize) + " m cell holds at most " +
                                std::to_string(m * m) + " raster cells, fewer than minPoints " +
                                std::to_string(options.minPoints));
  }
  if (!(options.minEigenRatio > 0.0 && options.minEigenRatio <= 1.0)) {
    throw Error("NDT grid", "minEigenRatio must be in (0, 1]");
  }
  // Raster cell (c, r) lies in NDT cell ((c + off.x) / m, (r + off.y) / m).
  const long long rasterX = std::llround(rg.origin.x() / res), rasterY = std::llround(rg.origin.y() / res);
  const int firstX = floorDiv(rasterX, m), firstY = floorDiv(rasterY, m);
  const int offX = int(rasterX - firstX * m), offY = int(rasterY - firstY * m);

  NdtGrid grid;
  GridGeometry& g = grid.geometry_;
  g.resolution = options.cellSize;
  g.origin = Eigen::Vector2d(firstX, firstY) * options.cellSize;
  g.cols = int((rg.cols + offX + m - 1) / m);
  g.rows = int((rg.rows + offY + m - 1) / m);

  // Accumulate one row of NDT cells at a time from the raster rows it covers.
  grid.index_.assign(g.cellCount(), -1);
  grid.cells_.reserve(raster.drivableCellCount() / size_t(m * m) * 2 + 16);
  std::vector<Moments> moments(size_t(g.cols));
  for (int ndtRow = 0; ndtRow < g.rows; ++ndtRow) {
    std::fill(moments.begin(), moments.end(), Moments{});
    const int first = std::max(0, int(ndtRow * m) - offY), last = std::min(rg.rows, int((ndtRow + 1) * m) - offY);
    for (int r = first; r < last; ++r) {
      const double y = ((r + offY) - ndtRow * m + 0.5) * res;
      for (const DrivableRaster::Run& run : raster.runs(r)) addRun(run, y, res, int(m), offX, moments);
    }
    for (int c = 0; c < g.cols; ++c) {
      const Moments& mo = moments[size_t(c)];
      if (mo.n < options.minPoints) continue;
      NdtCell cell;
      finishCell(mo, g.origin + Eigen::Vector2d(c, ndtRow) * g.resolution, res, options.minEigenRatio, cell);
      grid.index_[g.index(c, ndtRow)] = int32_t(grid.cells_.size());
      grid.cells_.push_back(cell);
    }
  }
  return grid;
}

const NdtCell* NdtGrid::at(int col, int row) const {
  if (!geometry_.inside(col, row)) return nullptr;
  const int32_t i = index_[geometry_.index(col, row)];
  return i < 0 ? nullptr : &cells_[size_t(i)];
}

const NdtCell* NdtGrid::cellAt(const Eigen::Vector2d& city) const {
  int col, row;
  return geometry_.cellOf(city, col, row) ? at(col, row) : nullptr;
}

}  // namespace hdprior
