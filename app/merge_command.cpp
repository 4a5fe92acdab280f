#include <filesystem>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/eval_logs.h"
#include "app/eval_merge.h"
#include "engine/error.h"

namespace hdprior::app {

int runMerge(const std::vector<std::string>& args) {
  const CommandLine cl(args, {.valued = {"logs"}, .flags = {}, .minPositional = 1, .maxPositional = 1,
                              .usage = "hdprior merge OUTDIR --logs DIR"});
  const std::filesystem::path out = cl.positional()[0];
  std::error_code ec;
  if (!std::filesystem::is_directory(out, ec)) {
    throw Error(out.string(), std::filesystem::exists(out, ec) ? "is not a folder" : "folder not found (where eval --out wrote)");
  }
  return mergeEvaluation(out, evalLogs(cl.required("logs")), "merge");
}

}  // namespace hdprior::app
