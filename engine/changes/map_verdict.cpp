#include "engine/changes/map_verdict.h"

namespace hdprior {

const char* verdictName(MapVerdict verdict) {
  switch (verdict) {
    case MapVerdict::Consistent: return "consistent";
    case MapVerdict::Contradicted: return "contradicted";
    case MapVerdict::Unobserved: return "unobserved";
  }
  return "unobserved";
}

}  // namespace hdprior
