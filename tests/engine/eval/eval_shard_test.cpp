#include <gtest/gtest.h>

#include "engine/error.h"
#include "engine/eval/eval_shard.h"

namespace hdprior {

TEST(EvalShard, ParsesIOfNZeroBased) {
  const EvalShard s = parseEvalShard("2/3");
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 3u);
  EXPECT_EQ(parseEvalShard("0/1").count, 1u);
}

TEST(EvalShard, RejectsWhatIsNotAShardNamingTheOption) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"3/3", "I must be below N"}, {"0/0", "N must be at least 1"}, {"1", "is not I/N"},
      {"-1/3", "is not I/N"},       {"a/3", "is not I/N"},           {"1/3x", "is not I/N"},
      {"/3", "is not I/N"},         {"1/", "is not I/N"},            {" 1/3", "is not I/N"}};
  for (const auto& [text, reason] : cases) {
    try {
      parseEvalShard(text);
      ADD_FAILURE() << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), "option --shard") << text;
      EXPECT_NE(e.reason().find(reason), std::string::npos) << text << " -> " << e.reason();
    }
  }
}

TEST(EvalShard, LogKGoesToShardKModN) {
  const std::vector<std::filesystem::path> logs = {"a", "b", "c", "d", "e"};
  EXPECT_EQ(logsOfShard(logs, {0, 2}), (std::vector<std::filesystem::path>{"a", "c", "e"}));
  EXPECT_EQ(logsOfShard(logs, {1, 2}), (std::vector<std::filesystem::path>{"b", "d"}));
  EXPECT_EQ(logsOfShard(logs, {0, 1}), logs);
  EXPECT_TRUE(logsOfShard(logs, {6, 7}).empty());  // more shards than logs: some have none
}

}  // namespace hdprior
