#pragma once
#include <string>

namespace CLI {
class ParseError;
}

namespace hdprior::app {

// CLI11's complaint about a command line in hdprior's words, naming the option or argument:
// "option --jobs: 'x' is not an integer", "option --out: is required", "option --bogus: unknown
// option", "option --odometry-drift: needs a value", "argument LOG: is required".
std::string parseErrorLine(const CLI::ParseError& error);

}  // namespace hdprior::app
