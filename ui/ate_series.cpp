#include "ui/ate_series.h"

#include <filesystem>

namespace hdprior::ui {
namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

std::vector<AteSeries> ateSeries(const render::Analysis& a) {
  std::vector<AteSeries> series;
  const bool runOverFile = !a.odometryFile.empty();
  if (!a.fileError.empty() && !(runOverFile && a.odometryFile == a.fileName))
    series.push_back({AteSeries::Kind::File, "file " + fileName(a.fileName), &a.fileError});
  if (!a.odometryError.empty()) {
    const std::string source = runOverFile ? "file " + fileName(a.odometryFile) : "built-in";
    const AteSeries::Kind kind = runOverFile ? AteSeries::Kind::File : AteSeries::Kind::Odometry;
    series.push_back({kind, "odometry (" + source + ")", &a.odometryError});
  }
  if (!a.optimizedError.empty()) series.push_back({AteSeries::Kind::Optimized, "optimised", &a.optimizedError});
  if (a.comparison) series.push_back({AteSeries::Kind::Comparison, "B: " + a.comparison->name, &a.comparison->optimizedError});
  return series;
}

}  // namespace hdprior::ui
