#include "ui/view_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "engine/map/hd_map.h"
#include "render/scene.h"

namespace hdprior::ui {

render::Camera ViewCamera::camera(double aspect) const {
  if (topDown) return render::topDownCamera(target, topHeight, aspect);
  return render::orbitCamera(target, yaw, pitch, distance, aspect);
}

void ViewCamera::orbit(double dx, double dy) {
  if (topDown) return;
  yaw -= dx * 0.006;
  pitch = std::clamp(pitch + dy * 0.006, 0.05, std::numbers::pi / 2 - 0.01);
}

void ViewCamera::pan(double dx, double dy, double viewportHeight) {
  followEgo = false;
  if (topDown) {
    const double metresPerPixel = topHeight / std::max(1.0, viewportHeight);
    target += Eigen::Vector3d(-dx, dy, 0) * metresPerPixel;
    return;
  }
  // Drag the ground along: right and forward on the map plane, scaled with the distance.
  const double metresPerPixel = 2.0 * distance * std::tan(0.4) / std::max(1.0, viewportHeight);
  const Eigen::Vector3d forward(std::cos(yaw), std::sin(yaw), 0), right(std::sin(yaw), -std::cos(yaw), 0);
  target += (-dx * right + dy * forward / std::max(0.2, std::sin(pitch))) * metresPerPixel;
}

void ViewCamera::zoom(double steps) {
  const double factor = std::pow(0.88, steps);
  distance = std::clamp(distance * factor, 3.0, 3000.0);
  topHeight = std::clamp(topHeight * factor, 5.0, 5000.0);
}

void ViewCamera::follow(const Eigen::Vector3d& egoLocal) {
  if (followEgo) target = egoLocal + Eigen::Vector3d(0, 0, 1.0);
}

std::optional<Eigen::Vector3d> pickGround(const render::Camera& camera, const Eigen::Vector2d& pixel, int width,
                                          int height, const render::Scene& scene, double fallbackZ) {
  if (width <= 0 || height <= 0) return std::nullopt;
  const Eigen::Matrix4d inverse = camera.viewProjection().cast<double>().inverse();
  const double x = 2.0 * (pixel.x() + 0.5) / width - 1.0, y = 1.0 - 2.0 * (pixel.y() + 0.5) / height;
  const auto unproject = [&](double z) {
    const Eigen::Vector4d p = inverse * Eigen::Vector4d(x, y, z, 1.0);
    return Eigen::Vector3d(p.head<3>() / p.w());
  };
  const Eigen::Vector3d nearPoint = unproject(-1.0), direction = unproject(1.0) - nearPoint;
  if (std::abs(direction.z()) < 1e-12) return std::nullopt;
  const GroundHeight* surface = scene.map && scene.map->hasGroundHeight() ? &scene.map->groundHeight() : nullptr;
  // Intersect with a plane at the ground height found under the last hit; a few rounds converge
  // on gently sloped ground.
  double z = fallbackZ;
  Eigen::Vector3d hit;
  for (int round = 0; round < 6; ++round) {
    const double t = (z - nearPoint.z()) / direction.z();
    if (t < 0.0 || t > 1.0) return std::nullopt;
    hit = nearPoint + t * direction;
    const double h = surface ? surface->bilinearAt(scene.origin.head<2>() + hit.head<2>()) : NAN;
    const double next = std::isfinite(h) ? h - scene.origin.z() : fallbackZ;
    if (std::abs(next - z) < 1e-3) break;
    z = next;
  }
  hit.z() = z;
  return hit;
}

}  // namespace hdprior::ui
