#include "app/command_line.h"

#include <cmath>

#include "engine/error.h"

namespace hdprior::app {

namespace {

// Short options spelled as their long form: -j 2 -> --jobs 2, -j2 -> --jobs=2.
std::vector<std::string> expandShortOptions(const std::vector<std::string>& args, const std::map<char, std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& a : args) {
    const auto it = a.size() >= 2 && a[0] == '-' && a[1] != '-' ? names.find(a[1]) : names.end();
    if (it == names.end()) {
      out.push_back(a);
    } else {
      std::string option = "--";
      option.append(it->second);
      if (a.size() > 2) option.append("=").append(a, 2);
      out.push_back(option);
    }
  }
  return out;
}

}  // namespace

CommandLine::CommandLine(const std::vector<std::string>& rawArgs, const Spec& spec) : usage_(spec.usage) {
  const std::vector<std::string> args = expandShortOptions(rawArgs, spec.shortNames);
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 || a.size() == 2) {
      positional_.push_back(a);
      continue;
    }
    std::string name = a.substr(2), inlineValue;
    const bool hasInline = name.find('=') != std::string::npos;
    if (hasInline) {
      inlineValue = name.substr(name.find('=') + 1);
      name = name.substr(0, name.find('='));
    }
    if (spec.flags.count(name) && !hasInline) {
      flags_.insert(name);
    } else if (spec.valued.count(name)) {
      if (hasInline) {
        values_[name] = inlineValue;
      } else if (i + 1 < args.size()) {
        values_[name] = args[++i];
      } else {
        throw Error("option --" + name, "needs a value (usage: " + usage_ + ")");
      }
    } else {
      throw Error("option --" + name, "unknown option (usage: " + usage_ + ")");
    }
  }
  if (positional_.size() < spec.minPositional || positional_.size() > spec.maxPositional) {
    throw Error("arguments", "expected " + std::to_string(spec.minPositional) +
                                 (spec.maxPositional != spec.minPositional ? "-" + std::to_string(spec.maxPositional) : "") +
                                 " positional argument(s), got " + std::to_string(positional_.size()) +
                                 " (usage: " + usage_ + ")");
  }
}

std::optional<std::string> CommandLine::value(const std::string& name) const {
  const auto it = values_.find(name);
  return it == values_.end() ? std::nullopt : std::optional(it->second);
}

std::string CommandLine::required(const std::string& name) const {
  const auto v = value(name);
  if (!v) throw Error("option --" + name, "is required (usage: " + usage_ + ")");
  return *v;
}

double CommandLine::number(const std::string& name, double fallback) const {
  const auto v = value(name);
  if (!v) return fallback;
  try {
    size_t used = 0;
    const double d = std::stod(*v, &used);
    if (used == v->size() && std::isfinite(d)) return d;
  } catch (const std::exception&) {
  }
  throw Error("option --" + name, "'" + *v + "' is not a number");
}

long long CommandLine::integer(const std::string& name, long long fallback) const {
  const auto v = value(name);
  if (!v) return fallback;
  try {
    size_t used = 0;
    const long long n = std::stoll(*v, &used);
    if (used == v->size()) return n;
  } catch (const std::exception&) {
  }
  throw Error("option --" + name, "'" + *v + "' is not an integer");
}

}  // namespace hdprior::app
