#pragma once
#include <filesystem>
#include <string>

#include "engine/eval/eval_summary.h"

namespace hdprior {

// A log's row of a batch evaluation, as a file: OUT/<log id>.result.json beside its run folder
// OUT/<log id>/. `hdprior eval` (any shard) writes one per log it ran, `merge` builds the tables
// from them. JSON keeps every figure the tables need at full precision (numbers round-trip
// exactly) and the priors the calibration pools; a trajectory keeps its statistics, not its
// per-sweep errors.
std::filesystem::path logEvaluationFile(const std::filesystem::path& out, const std::string& logId);

// Written atomically (temporary name, rename); throws Error naming the file.
void writeLogEvaluation(const std::filesystem::path& file, const LogEvaluation& log);

// Throws Error naming the file and the problem when it is missing, not JSON or lacks a field.
LogEvaluation readLogEvaluation(const std::filesystem::path& file);

}  // namespace hdprior
