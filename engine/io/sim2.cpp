#include "engine/io/sim2.h"

#include <cmath>

#include <Eigen/LU>

#include "engine/io/file_bytes.h"
#include "engine/io/json_reading.h"

namespace hdprior {
using namespace json_reading;

Sim2 parseSim2(const std::string& text, const std::string& source) {
  const nlohmann::json j = parse(text, source);
  const nlohmann::json& r = member(j, "R", "Sim2", source);
  const nlohmann::json& t = member(j, "t", "Sim2", source);
  if (!r.is_array() || r.size() != 4) throw Error(source, "Sim2 'R' must be an array of 4 numbers");
  if (!t.is_array() || t.size() != 2) throw Error(source, "Sim2 't' must be an array of 2 numbers");
  Sim2 sim;
  sim.R << number(r[0], "R[0]", source), number(r[1], "R[1]", source), number(r[2], "R[2]", source),
      number(r[3], "R[3]", source);
  sim.t << number(t[0], "t[0]", source), number(t[1], "t[1]", source);
  sim.s = number(member(j, "s", "Sim2", source), "s", source);
  if (!(sim.s > 0)) throw Error(source, "Sim2 scale s must be positive");
  if ((sim.R * sim.R.transpose() - Eigen::Matrix2d::Identity()).norm() > 1e-6 || sim.R.determinant() < 0) {
    throw Error(source, "Sim2 'R' is not a rotation matrix");
  }
  return sim;
}

Sim2 readSim2(const std::filesystem::path& path) { return parseSim2(readFileText(path), path.string()); }

std::string sim2ToJson(const Sim2& sim) {
  nlohmann::json j;
  j["R"] = {sim.R(0, 0), sim.R(0, 1), sim.R(1, 0), sim.R(1, 1)};
  j["t"] = {sim.t.x(), sim.t.y()};
  j["s"] = sim.s;
  return j.dump();
}

}  // namespace hdprior
