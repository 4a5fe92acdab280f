#pragma once
#include <optional>

#include <Eigen/Core>

#include "render/camera.h"

namespace hdprior::render {
struct Scene;
}

namespace hdprior::ui {

// The app's interactive camera, in the scene frame (city minus Scene::origin): an orbit view
// around `target` or a north-up top-down view centred on it. Follows the ego unless panned.
struct ViewCamera {
  bool topDown = false;
  bool followEgo = true;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double yaw = 0.0;         // direction the orbit camera looks, counter-clockwise from +x
  double pitch = 0.6;       // below the horizon, radians
  double distance = 60.0;   // orbit: metres from the target
  double topHeight = 90.0;  // top-down: metres shown vertically

  render::Camera camera(double aspect) const;
  // Mouse drags in pixels over a viewport `viewportHeight` pixels high.
  void orbit(double dx, double dy);
  void pan(double dx, double dy, double viewportHeight);
  // Positive steps zoom in (mouse wheel notches or key presses).
  void zoom(double steps);
  // Puts the target on the ego (when following).
  void follow(const Eigen::Vector3d& egoLocal);
};

// The point of the ground under a pixel (x right, y down, in a width x height viewport): the
// camera ray intersected with the ground-height surface (the plane z = fallbackZ, scene frame,
// where the raster has no height). Nothing when the ray misses the ground (the sky).
std::optional<Eigen::Vector3d> pickGround(const render::Camera& camera, const Eigen::Vector2d& pixel, int width,
                                          int height, const render::Scene& scene, double fallbackZ);

}  // namespace hdprior::ui
