#include "engine/io/ground_labels.h"

#include <string>

#include "engine/error.h"
#include "engine/io/feather.h"

namespace hdprior {

std::vector<uint8_t> readGroundLabels(const std::filesystem::path& file, size_t points) {
  const arrow::Table table = arrow::readFeather(file);
  const arrow::Column& column = table.column("is_ground_0", arrow::Type::Bool, file.string());
  if (size_t(column.length) != points) {
    throw Error(file.string(), "has " + std::to_string(column.length) + " rows, the sweep " + std::to_string(points) + " points");
  }
  if (column.nullCount() > 0) throw Error(file.string(), "is_ground_0 has " + std::to_string(column.nullCount()) + " missing values");
  return column.values;
}

}  // namespace hdprior
