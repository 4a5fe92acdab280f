#include "engine/match/pcl_ndt_backend.h"

#include <algorithm>
#include <cmath>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/ndt.h>

#include "engine/error.h"
#include "engine/map/drivable_raster.h"

namespace hdprior {

struct PclNdtBackend::Impl {
  Eigen::Vector2d origin;
  pcl::PointCloud<pcl::PointXYZ>::Ptr target{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::NormalDistributionsTransform<pcl::PointXYZ, pcl::PointXYZ> ndt;
};

PclNdtBackend::PclNdtBackend(const DrivableRaster& drivable, const MatchOptions& o) : impl_(std::make_unique<Impl>()) {
  if (!(o.pclResolution > 0 && o.pclStepSize > 0 && o.pclEpsilon > 0 && o.pclMaxIterations > 0 &&
        o.pclTargetSpacing >= drivable.geometry().resolution)) {
    throw Error("match options", "PCL NDT resolution, step size, epsilon, iterations or target spacing out of range");
  }
  const GridGeometry& g = drivable.geometry();
  impl_->origin = g.origin;
  const int every = std::max(1, int(std::lround(o.pclTargetSpacing / g.resolution)));
  for (int row = 0; row < g.rows; row += every) {
    for (const DrivableRaster::Run& run : drivable.runs(row)) {
      for (int col = (run.begin + every - 1) / every * every; col < run.end; col += every) {
        const Eigen::Vector2d c = g.cellCentre(col, row) - impl_->origin;
        impl_->target->push_back(pcl::PointXYZ(float(c.x()), float(c.y()), 0.0f));
      }
    }
  }
  impl_->ndt.setResolution(float(o.pclResolution));
  impl_->ndt.setStepSize(o.pclStepSize);
  impl_->ndt.setTransformationEpsilon(o.pclEpsilon);
  impl_->ndt.setMaximumIterations(o.pclMaxIterations);
  impl_->ndt.setOulierRatio(o.outlierRatio);
  impl_->ndt.setInputTarget(impl_->target);
  if (impl_->target->empty()) throw Error("PCL NDT", "the map has no drivable points");
  // PCL builds its voxel grid on the first alignment; do that here, not inside a timed match.
  std::vector<Eigen::Vector2d> probe;
  for (size_t i = 0; i < std::min<size_t>(impl_->target->size(), 8); ++i) {
    probe.push_back(impl_->target->at(i).getVector3fMap().head<2>().cast<double>());
  }
  align(probe, Eigen::Vector3d(impl_->origin.x(), impl_->origin.y(), 0.0));
}

PclNdtBackend::~PclNdtBackend() = default;

size_t PclNdtBackend::targetPoints() const { return impl_->target->size(); }

PclNdtBackend::Alignment PclNdtBackend::align(std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& initial) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr source(new pcl::PointCloud<pcl::PointXYZ>);
  source->reserve(points.size());
  for (const Eigen::Vector2d& p : points) source->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), 0.0f));
  impl_->ndt.setInputSource(source);
  Eigen::Matrix4f guess = Eigen::Matrix4f::Identity();
  const float c = float(std::cos(initial.z())), s = float(std::sin(initial.z()));
  guess(0, 0) = c;
  guess(0, 1) = -s;
  guess(1, 0) = s;
  guess(1, 1) = c;
  guess(0, 3) = float(initial.x() - impl_->origin.x());
  guess(1, 3) = float(initial.y() - impl_->origin.y());
  pcl::PointCloud<pcl::PointXYZ> aligned;
  impl_->ndt.align(aligned, guess);
  const Eigen::Matrix4f T = impl_->ndt.getFinalTransformation();
  Alignment a;
  a.pose = Eigen::Vector3d(double(T(0, 3)) + impl_->origin.x(), double(T(1, 3)) + impl_->origin.y(),
                           std::atan2(double(T(1, 0)), double(T(0, 0))));
  a.iterations = impl_->ndt.getFinalNumIteration();
  a.converged = impl_->ndt.hasConverged();
  return a;
}

}  // namespace hdprior
