#pragma once
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

// A value stored as one of its names: an enum, or a string with a closed set of values.
struct OptionChoice {
  std::vector<const char*> names;
  std::function<size_t()> get;
  std::function<void(size_t)> set;
};

template <class E>
OptionChoice optionChoice(E* e, std::vector<const char*> names) {
  return {std::move(names), [e] { return size_t(*e); }, [e](size_t i) { *e = E(i); }};
}
OptionChoice optionChoice(std::string* s, std::vector<const char*> names);

// "[0, 1)": a closed end with a bracket, an open one with a parenthesis.
struct OptionRange {
  double lo = 0, hi = 0;
  bool loOpen = false, hiOpen = false;

  explicit OptionRange(std::string_view text);
  bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
};

// One tunable option of an engine stage, declared once next to its options struct: its
// configuration key, the member that holds it (whose initialiser is the default), its range, unit and
// a one-line description. The configuration's schema (engine/pipeline/config.cpp) is made of these,
// and each stage's constructor checks its options against the same declarations.
struct OptionField {
  const char* key;  // within its section: "min_points"
  std::variant<int*, double*, std::vector<double>*, Eigen::Vector3d*, OptionChoice> value;
  const char* range;  // of a number, or of every element of an array; "" for a choice
  const char* unit;
  const char* description;
};

// Throws Error(what, "min_points = 0 is out of range [1, 10000000]") for the first field whose value
// (or an element of it, or an empty array, or a choice outside its names) the declaration refuses.
void checkOptionRanges(const std::string& what, const std::vector<OptionField>& fields);

}  // namespace hdprior
