#pragma once

namespace hdprior {

// What the lidar says of a map element, or of a stretch of one.
enum class MapVerdict { Consistent, Contradicted, Unobserved };

// "consistent", "contradicted", "unobserved".
const char* verdictName(MapVerdict verdict);

}  // namespace hdprior
