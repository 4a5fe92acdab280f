#pragma once
#include <optional>
#include <span>

#include <Eigen/Core>

#include "engine/sim/scene.h"

namespace hdprior {

struct RayHit {
  double range = 0.0;         // metres along the unit direction
  PointLabel label = PointLabel::Object;
  double cosIncidence = 1.0;  // |cos| of the angle between the ray and the surface normal
  uint8_t reflectivity = 0;   // of the surface material, 0..255
};

// The first surface of the scene along origin + t * dir (dir a unit vector, t in (0,
// maxRange]): static objects through the 2-D grid (DDA), `moving` boxes by brute force, and
// the ground by Lipschitz-bounded marching on the height field (curb step included), refined
// by bisection. nullopt if nothing is hit.
std::optional<RayHit> castRay(const Scene& scene, std::span<const SceneBox> moving, const Eigen::Vector3d& origin,
                              const Eigen::Vector3d& dir, double maxRange);

// The pieces, for tests and benchmarks.
std::optional<RayHit> castRayObjects(const Scene& scene, std::span<const SceneBox> moving,
                                     const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double maxRange);
std::optional<RayHit> castRayGround(const Scene& scene, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                    double maxRange);

}  // namespace hdprior
