// One wrong way to call a command, for the parameterised tests of refused input.
#pragma once
#include <ostream>
#include <string>

namespace hdprior::test {

struct BadInput {
  const char* name;     // the case's name in the test output
  std::string args;     // the command line, as each suite spells it
  const char* message;  // what the one line on stderr holds
};
inline void PrintTo(const BadInput& b, std::ostream* os) { *os << b.name; }

}  // namespace hdprior::test
