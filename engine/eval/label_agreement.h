#pragma once
#include <cstdint>
#include <span>

namespace hdprior {

// How a per-point labelling (ground, road) agrees with a reference labelling of the same points,
// such as the Argoverse 2 scene-flow annotations' is_ground_0.
struct LabelAgreement {
  int64_t truePositive = 0;   // labelled, and so in the reference
  int64_t falsePositive = 0;  // labelled, not in the reference
  int64_t falseNegative = 0;  // in the reference, not labelled
  int64_t trueNegative = 0;

  double precision() const;  // of the points labelled, the share the reference labels too (NaN if none)
  double recall() const;     // of the reference's points, the share labelled (NaN if none)
};

// `labelled` and `reference`: nonzero where each says yes; both over the same points in the same order.
// Throws Error when their lengths differ.
LabelAgreement labelAgreement(std::span<const uint8_t> labelled, std::span<const uint8_t> reference);

}  // namespace hdprior
