#pragma once
#include <stdexcept>
#include <string>

namespace hdprior {

// The one exception type of the engine: which file (or option) is wrong and why.
// Every command turns it into one line on stderr and exit status 2.
class Error : public std::runtime_error {
 public:
  Error(std::string file, std::string reason)
      : std::runtime_error(file + ": " + reason), file_(std::move(file)), reason_(std::move(reason)) {}

  const std::string& file() const { return file_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  std::string reason_;
};

}  // namespace hdprior
