#pragma once
#include <optional>

#include <Eigen/Core>

namespace hdprior::render {

// View and projection of one picture, in the scene's local frame (city minus Scene::origin).
struct Camera {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f viewProjection() const { return projection * view; }
  // Metres on the ground per pixel of a viewport `viewportHeight` pixels high: the same
  // everywhere in an orthographic (top-down) view; none for a perspective one.
  std::optional<double> metresPerPixel(int viewportHeight) const;
};

// Bird's-eye view: north up, looking down at `centre`, showing `height` metres vertically.
Camera topDownCamera(const Eigen::Vector3d& centre, double height, double aspect);

// Perspective view of `target` from `distance` metres, at compass direction `yaw` (radians,
// the direction the camera looks, counter-clockwise from +x) and `pitch` below the horizon.
Camera orbitCamera(const Eigen::Vector3d& target, double yaw, double pitch, double distance, double aspect,
                   double fovY = 0.8);

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up);
Eigen::Matrix4f perspective(float fovY, float aspect, float near, float far);
Eigen::Matrix4f orthographic(float left, float right, float bottom, float top, float near, float far);

}  // namespace hdprior::render
