#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/eval_logs.h"
#include "app/eval_merge.h"
#include "engine/error.h"

namespace hdprior::app {
namespace {

struct MergeArguments {
  std::string out, logs;
};

int runMerge(const MergeArguments& a) {
  const std::filesystem::path out = a.out;
  std::error_code ec;
  if (!std::filesystem::is_directory(out, ec)) {
    throw Error(out.string(), std::filesystem::exists(out, ec) ? "is not a folder" : "folder not found (where eval --out wrote)");
  }
  return mergeEvaluation(out, evalLogs(a.logs), "merge");
}

}  // namespace

Command addMergeCommand(CLI::App& hdprior) {
  CLI::App* command = hdprior.add_subcommand(
      "merge", "the tables of a sharded eval (per_log.csv, table.md, table.csv, rmse_boxplot.png) from its per-log results");
  auto a = std::make_shared<MergeArguments>();
  command->add_option("OUTDIR", a->out, "where the shards of `eval DIR --out OUTDIR --shard I/N` wrote")->required();
  command->add_option("--logs", a->logs, "the DIR the shards evaluated")->type_name("DIR")->required();
  return {command, [a] { return runMerge(*a); }};
}

}  // namespace hdprior::app
