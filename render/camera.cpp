#include "render/camera.h"

#include <cmath>

#include <Eigen/Geometry>

namespace hdprior::render {

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up) {
  const Eigen::Vector3f f = (target - eye).normalized();
  const Eigen::Vector3f s = f.cross(up).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4f perspective(float fovY, float aspect, float near, float far) {
  const float t = 1.0f / std::tan(fovY / 2);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2 * far * near / (near - far);
  m(3, 2) = -1;
  return m;
}

Eigen::Matrix4f orthographic(float left, float right, float bottom, float top, float near, float far) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 2 / (right - left);
  m(1, 1) = 2 / (top - bottom);
  m(2, 2) = -2 / (far - near);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

std::optional<double> Camera::metresPerPixel(int viewportHeight) const {
  const bool orthographic = projection(3, 3) == 1.0f && projection(3, 2) == 0.0f;
  if (!orthographic || viewportHeight <= 0) return std::nullopt;
  return 2.0 / (double(projection(1, 1)) * viewportHeight);  // clip y spans 2
}

Camera topDownCamera(const Eigen::Vector3d& centre, double height, double aspect) {
  const Eigen::Vector3f c = centre.cast<float>();
  const float h = float(height) / 2, w = h * float(aspect);
  Camera camera;
  camera.view = lookAt(c + Eigen::Vector3f(0, 0, 500), c, Eigen::Vector3f::UnitY());
  camera.projection = orthographic(-w, w, -h, h, 1.0f, 1000.0f);
  return camera;
}

Camera orbitCamera(const Eigen::Vector3d& target, double yaw, double pitch, double distance, double aspect,
                   double fovY) {
  const Eigen::Vector3d look(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), -std::sin(pitch));
  const Eigen::Vector3f eye = (target - distance * look).cast<float>();
  Camera camera;
  camera.view = lookAt(eye, target.cast<float>(), Eigen::Vector3f::UnitZ());
  camera.projection = perspective(float(fovY), float(aspect), 0.5f, float(20 * distance + 1000));
  return camera;
}

}  // namespace hdprior::render
