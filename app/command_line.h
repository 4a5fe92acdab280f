#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace hdprior::app {

// The arguments of one subcommand: positionals and --key value / --flag options, checked
// against what the command accepts. Problems throw Error("option --x", reason).
class CommandLine {
 public:
  struct Spec {
    std::set<std::string> valued;  // options that take a value: --out DIR
    std::set<std::string> flags;   // options without a value: --no-prior
    size_t minPositional = 0, maxPositional = 0;
    std::string usage;
    std::map<char, std::string> shortNames = {};  // {'j', "jobs"}: -j N and -jN mean --jobs N
  };

  CommandLine(const std::vector<std::string>& args, const Spec& spec);

  const std::vector<std::string>& positional() const { return positional_; }
  bool has(const std::string& name) const { return values_.count(name) || flags_.count(name); }
  std::optional<std::string> value(const std::string& name) const;
  std::string required(const std::string& name) const;
  double number(const std::string& name, double fallback) const;
  long long integer(const std::string& name, long long fallback) const;

 private:
  std::string usage_;
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
};

}  // namespace hdprior::app
