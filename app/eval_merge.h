#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace hdprior::app {

// The last step of every batch evaluation (`hdprior merge`, and a plain `hdprior eval` after it
// ran all the logs): per_log.csv, table.md, table.csv and rmse_boxplot.png in `out`, built from the
// result file of each of `logs` (log_evaluation_file.h), in their order; prints the table. A log
// without a result file is missing: its row carries that as its error and it counts as failed.
// Each missing or failed log gets one stderr line "hdprior <command>: log <id>: <problem>".
// Returns the exit status: 2 when any log is missing or failed, else 0. A result file that cannot
// be read throws Error before anything is written.
int mergeEvaluation(const std::filesystem::path& out, const std::vector<std::filesystem::path>& logs,
                    const std::string& command);

}  // namespace hdprior::app
