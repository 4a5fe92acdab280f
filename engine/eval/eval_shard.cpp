#include "engine/eval/eval_shard.h"

#include <charconv>
#include <optional>

#include "engine/error.h"

namespace hdprior {
namespace {

// Digits only: no sign, no spaces.
std::optional<size_t> count(const std::string& s) {
  size_t n = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return n;
}

}  // namespace

EvalShard parseEvalShard(const std::string& text) {
  const size_t slash = text.find('/');
  const std::string option = "option --shard";
  if (slash == std::string::npos) throw Error(option, "'" + text + "' is not I/N (shard I of N, 0-based)");
  const auto index = count(text.substr(0, slash)), shards = count(text.substr(slash + 1));
  if (!index || !shards) throw Error(option, "'" + text + "' is not I/N (shard I of N, 0-based)");
  if (*shards == 0) throw Error(option, "'" + text + "': N must be at least 1");
  if (*index >= *shards) throw Error(option, "'" + text + "': I must be below N (shards are 0-based: 0 to " + std::to_string(*shards - 1) + ")");
  return {*index, *shards};
}

std::vector<std::filesystem::path> logsOfShard(const std::vector<std::filesystem::path>& logs, EvalShard shard) {
  std::vector<std::filesystem::path> mine;
  for (size_t k = shard.index; k < logs.size(); k += shard.count) mine.push_back(logs[k]);
  return mine;
}

}  // namespace hdprior
