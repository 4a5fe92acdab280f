#include "ui/view_session.h"

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/io/file_bytes.h"

namespace hdprior::ui {
namespace {

using json = nlohmann::json;

constexpr int kVersion = 1;

json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Eigen::Vector3d vectorOf(const json& j) {
  if (!j.is_array() || j.size() != 3) throw std::invalid_argument("expected [x, y, z]");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

json cameraJson(const ViewSession::Camera& c) {
  return {{"top_down", c.topDown}, {"follow_ego", c.followEgo}, {"target", vectorJson(c.target)}, {"yaw", c.yaw},
          {"pitch", c.pitch}, {"distance", c.distance}, {"top_height", c.topHeight}};
}

ViewSession::Camera cameraOf(const json& j) {
  return {.topDown = j.at("top_down").get<bool>(), .followEgo = j.at("follow_ego").get<bool>(),
          .target = vectorOf(j.at("target")), .yaw = j.at("yaw").get<double>(), .pitch = j.at("pitch").get<double>(),
          .distance = j.at("distance").get<double>(), .topHeight = j.at("top_height").get<double>()};
}

json sessionJson(const ViewSession& s) {
  json layers = json::array(), bookmarks = json::array();
  for (const auto& l : s.layers) layers.push_back({{"name", l.name}, {"visible", l.visible}, {"opacity", l.opacity}});
  for (const auto& b : s.bookmarks) bookmarks.push_back({{"frame", b.frame}, {"note", b.note}});
  json j = {{"hdprior_view_session", kVersion}, {"log", s.log.string()}, {"frame", s.frame},
            {"camera", cameraJson(s.camera)}, {"layers", layers}, {"tab", s.tab}, {"plots", s.plots},
            {"bookmarks", bookmarks}, {"config", json::parse(s.config.empty() ? "{}" : s.config)}, {"ran", s.ran},
            {"keyframe", s.keyframe ? json(*s.keyframe) : json(nullptr)}, {"comparison", nullptr}};
  if (const auto& b = s.comparison) {
    j["comparison"] = {{"name", b->name}, {"config", json::parse(b->config)},
                       {"file", b->file ? json(b->file->string()) : json(nullptr)}};
  }
  return j;
}

ViewSession sessionOf(const json& j) {
  if (j.at("hdprior_view_session").get<int>() != kVersion) throw std::invalid_argument("an unknown session version");
  ViewSession s;
  s.log = j.at("log").get<std::string>();
  s.frame = j.at("frame").get<size_t>();
  s.camera = cameraOf(j.at("camera"));
  for (const json& l : j.at("layers"))
    s.layers.push_back({l.at("name").get<std::string>(), l.at("visible").get<bool>(), l.at("opacity").get<float>()});
  s.tab = j.at("tab").get<std::string>();
  s.plots = j.at("plots").get<std::vector<std::string>>();
  for (const json& b : j.at("bookmarks")) s.bookmarks.push_back({b.at("frame").get<size_t>(), b.at("note").get<std::string>()});
  s.config = j.at("config").dump();
  s.ran = j.at("ran").get<bool>();
  if (!j.at("keyframe").is_null()) s.keyframe = j.at("keyframe").get<size_t>();
  if (const json& b = j.at("comparison"); !b.is_null()) {
    s.comparison = ViewSession::Comparison{b.at("name").get<std::string>(), b.at("config").dump(), std::nullopt};
    if (!b.at("file").is_null()) s.comparison->file = b.at("file").get<std::string>();
  }
  return s;
}

}  // namespace

ViewCamera viewCameraOf(const ViewSession::Camera& c, const Eigen::Vector3d& origin) {
  ViewCamera v;
  v.topDown = c.topDown;
  v.followEgo = c.followEgo;
  v.target = c.target - origin;
  v.yaw = c.yaw;
  v.pitch = c.pitch;
  v.distance = c.distance;
  v.topHeight = c.topHeight;
  return v;
}

ViewSession::Camera sessionCameraOf(const ViewCamera& c, const Eigen::Vector3d& origin) {
  return {.topDown = c.topDown, .followEgo = c.followEgo, .target = c.target + origin, .yaw = c.yaw, .pitch = c.pitch,
          .distance = c.distance, .topHeight = c.topHeight};
}

void writeViewSession(const std::filesystem::path& file, const ViewSession& session) {
  writeFileAtomically(file, sessionJson(session).dump(2) + "\n");
}

ViewSession readViewSession(const std::filesystem::path& file) {
  const std::string text = readFileText(file);
  try {
    return sessionOf(json::parse(text));
  } catch (const json::exception& e) {
    throw Error(file.string(), std::string("not a view session: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw Error(file.string(), std::string("not a view session: ") + e.what());
  }
}

}  // namespace hdprior::ui
