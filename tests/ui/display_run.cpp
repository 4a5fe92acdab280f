#include "display_run.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace hdprior::test {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

CommandResult runWithDisplay(const std::string& args, const std::filesystem::path& dir, const std::string& env) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = env + " xvfb-run -a -f " + quoted(dir / "Xauthority") + " -s '-screen 0 1280x800x24' '" +
                          std::string(HDPRIOR_BINARY) + "' " + args + " >" + quoted(out) + " 2>" + quoted(err);
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace hdprior::test
