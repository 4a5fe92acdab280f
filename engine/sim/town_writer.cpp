#include "engine/sim/town_writer.h"

#include <system_error>

#include "engine/error.h"
#include "engine/io/file_bytes.h"

namespace hdprior {

void writeTownMap(const std::filesystem::path& dir, const std::string& logId, const std::string& city,
                  const TownMap& town) {
  if (logId.empty() || city.empty()) throw Error(dir.string(), "empty log id or city name");
  const std::filesystem::path mapDir = dir / "map";
  std::error_code ec;
  std::filesystem::create_directories(mapDir, ec);
  if (ec) throw Error(mapDir.string(), "cannot create directory: " + ec.message());
  const std::string cityNumber = std::to_string(town.seed % 100000);
  writeFileAtomically(mapDir / ("log_map_archive_" + logId + "____" + city + "_city_" + cityNumber + ".json"),
                      vectorMapToJson(town.vectorMap));
  writeNpy(mapDir / (logId + "_ground_height_surface____" + city + ".npy"), town.groundHeight);
  writeFileAtomically(mapDir / (logId + "___img_Sim2_city.json"), sim2ToJson(town.imgSim2City));
}

}  // namespace hdprior
