// Reading back what `hdprior run` printed and wrote, for the tests of the command.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace hdprior::test {

// The run's metrics.json in its output folder.
inline nlohmann::json metricsOf(const std::filesystem::path& out) {
  std::ifstream in(out / "metrics.json");
  return nlohmann::json::parse(in);
}

// The first line of printed text, with its newline.
inline std::string oneLine(const std::string& s) { return s.substr(0, s.find('\n') + 1); }

}  // namespace hdprior::test
