#include "engine/eval/label_agreement.h"

#include <cmath>
#include <string>

#include "engine/error.h"

namespace hdprior {

double LabelAgreement::precision() const {
  const int64_t labelled = truePositive + falsePositive;
  return labelled > 0 ? double(truePositive) / double(labelled) : NAN;
}

double LabelAgreement::recall() const {
  const int64_t reference = truePositive + falseNegative;
  return reference > 0 ? double(truePositive) / double(reference) : NAN;
}

LabelAgreement labelAgreement(std::span<const uint8_t> labelled, std::span<const uint8_t> reference) {
  if (labelled.size() != reference.size()) {
    throw Error("label agreement", std::to_string(labelled.size()) + " labelled points against " +
                                       std::to_string(reference.size()) + " in the reference");
  }
  LabelAgreement a;
  for (size_t i = 0; i < labelled.size(); ++i) {
    const bool yes = labelled[i] != 0, truth = reference[i] != 0;
    (yes ? (truth ? a.truePositive : a.falsePositive) : (truth ? a.falseNegative : a.trueNegative))++;
  }
  return a;
}

}  // namespace hdprior
