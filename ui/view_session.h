#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ui/event_navigation.h"
#include "ui/view_camera.h"

namespace hdprior::ui {

// A saved `hdprior view` session: what the user looked at and how, to come back to it or to render
// it headless (`hdprior snapshot --session`). Positions are in the city frame.
struct ViewSession {
  struct Camera {
    bool topDown = false, followEgo = true;
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  // city
    double yaw = 0.0, pitch = 0.6, distance = 60.0, topHeight = 90.0;
  };
  struct Layer {
    std::string name;
    bool visible = true;
    float opacity = 1.0f;
  };
  // Run B of the comparison: its name and configuration, and the file it came from if any.
  struct Comparison {
    std::string name;
    std::string config;  // JSON, every key
    std::optional<std::filesystem::path> file;
  };

  std::filesystem::path log;
  size_t frame = 0;
  Camera camera;
  std::vector<Layer> layers;
  std::string tab;
  std::vector<std::string> plots;
  std::vector<Bookmark> bookmarks;
  std::string config;                // run A's configuration (JSON, every key)
  bool ran = false;                  // run A was run: restoring runs it again
  std::optional<size_t> keyframe;    // the inspected keyframe
  std::optional<Comparison> comparison;
};

// The app's camera from a session's and back; `origin` is the scene's (ViewCamera is scene-local).
ViewCamera viewCameraOf(const ViewSession::Camera& camera, const Eigen::Vector3d& origin);
ViewSession::Camera sessionCameraOf(const ViewCamera& camera, const Eigen::Vector3d& origin);

// Writes atomically; throws Error naming the file.
void writeViewSession(const std::filesystem::path& file, const ViewSession& session);
// Throws Error naming the file and what is wrong (missing, not JSON, a field missing or mistyped).
ViewSession readViewSession(const std::filesystem::path& file);

}  // namespace hdprior::ui
