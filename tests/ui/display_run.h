#pragma once
#include <filesystem>
#include <string>

#include "test_data.h"

namespace hdprior::test {

// quoted(path): test_data.h.
// The whole file (empty if it cannot be read).
std::string slurp(const std::filesystem::path& p);
void writeText(const std::filesystem::path& path, const std::string& text);

// Runs `hdprior ARGS` under a fresh virtual X server (xvfb-run, 1280x800), as CI does; stdout and
// stderr go to files in `dir`. The X authority file is the test's own (-f): xvfb-run then has no
// temporary folder to remove, whose removal sometimes fails under load and turns the command's exit
// status into 5.
CommandResult runWithDisplay(const std::string& args, const std::filesystem::path& dir, const std::string& env = "");

}  // namespace hdprior::test
