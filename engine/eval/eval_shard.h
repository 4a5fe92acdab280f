#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace hdprior {

// One share of a batch evaluation, as `hdprior eval --shard I/N` runs it (a task of a job array):
// 0-based index I of N shards. Log k of the logs sorted by path goes to shard k mod N.
struct EvalShard {
  size_t index = 0, count = 1;
};

// "I/N" with 0 <= I < N; throws Error("option --shard", reason) otherwise.
EvalShard parseEvalShard(const std::string& text);

// The logs of `shard`, in their order; `logs` sorted by path.
std::vector<std::filesystem::path> logsOfShard(const std::vector<std::filesystem::path>& logs, EvalShard shard);

}  // namespace hdprior
