#include "engine/option_fields.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "engine/error.h"

namespace hdprior {

OptionChoice optionChoice(std::string* s, std::vector<const char*> names) {
  return {names, [s, names] { return size_t(std::find(names.begin(), names.end(), *s) - names.begin()); },
          [s, names](size_t i) { *s = names[i]; }};
}

OptionRange::OptionRange(std::string_view text) {
  const std::string t(text);
  char* end = nullptr;
  loOpen = t.front() == '(';
  lo = std::strtod(t.c_str() + 1, &end);
  hi = std::strtod(end + 1, &end);
  hiOpen = *end == ')';
}

namespace {

std::string shortest(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The refusal of one field's value, or "" when its declaration accepts it.
struct Refusal {
  const OptionField& f;
  std::string operator()(const int* p) const { return ofNumber(*p); }
  std::string operator()(const double* p) const { return ofNumber(*p); }
  std::string operator()(const std::vector<double>* p) const {
    if (p->empty()) return std::string(f.key) + " is empty";
    for (double v : *p) {
      if (std::string why = ofNumber(v); !why.empty()) return why;
    }
    return "";
  }
  std::string operator()(const Eigen::Vector3d* p) const {
    for (double v : *p) {
      if (std::string why = ofNumber(v); !why.empty()) return why;
    }
    return "";
  }
  std::string operator()(const OptionChoice& c) const {
    if (c.get() < c.names.size()) return "";
    std::string names;
    for (const char* n : c.names) names += std::string(names.empty() ? "" : ", ") + n;
    return std::string(f.key) + " must be one of " + names;
  }
  std::string ofNumber(double v) const {
    return OptionRange(f.range).contains(v) ? "" : std::string(f.key) + " = " + shortest(v) + " is out of range " + f.range;
  }
};

}  // namespace

void checkOptionRanges(const std::string& what, const std::vector<OptionField>& fields) {
  for (const OptionField& f : fields) {
    if (std::string why = std::visit(Refusal{f}, f.value); !why.empty()) throw Error(what, why);
  }
}

}  // namespace hdprior
