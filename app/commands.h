#pragma once
#include <string>
#include <vector>

namespace hdprior::app {

// Each subcommand takes its arguments (after the subcommand name) and returns the exit status.
// Bad input throws hdprior::Error, which main turns into one line and exit status 2.
int runInfo(const std::vector<std::string>& args);
int runExportMap(const std::vector<std::string>& args);
int runSnapshot(const std::vector<std::string>& args);
int runRun(const std::vector<std::string>& args);
int runSim(const std::vector<std::string>& args);
int runMatch(const std::vector<std::string>& args);
int runView(const std::vector<std::string>& args);
int runDemo(const std::vector<std::string>& args);
int runEval(const std::vector<std::string>& args);
int runMerge(const std::vector<std::string>& args);
int runDegradeTrajectory(const std::vector<std::string>& args);

}  // namespace hdprior::app
