#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/progress_bar.h"

namespace hdprior::app {
namespace {

// What a ProgressBar writes for the calls done = 0, 1, ..., total (as `run` calls it).
std::string written(bool terminal, size_t total) {
  char* buffer = nullptr;
  size_t size = 0;
  std::FILE* out = open_memstream(&buffer, &size);
  EXPECT_NE(out, nullptr);
  {
    ProgressBar bar("run", "sweeps", out, terminal);
    for (size_t done = 0; done <= total; ++done) bar(done, total);
  }
  std::fclose(out);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

size_t count(const std::string& text, char c) { return size_t(std::count(text.begin(), text.end(), c)); }

}  // namespace

TEST(ProgressBar, OnATerminalRedrawsOneBarInPlace) {
  const std::string text = written(true, 200);
  EXPECT_EQ(count(text, '\n'), 1u);     // the finished bar ends the line
  EXPECT_EQ(count(text, '\r'), 41u);    // one frame per change of the 40-character bar, and 0
  EXPECT_NE(text.find("\rrun [" + std::string(40, '#') + "] 200/200 sweeps\n"), std::string::npos) << text;
}

TEST(ProgressBar, ElsewhereOnePlainLineEveryTenPercent) {
  const std::string text = written(false, 200);
  EXPECT_EQ(count(text, '\r'), 0u);
  EXPECT_EQ(count(text, '\n'), 10u);
  EXPECT_EQ(text.rfind("run: 10 % (20/200 sweeps)\nrun: 20 % (40/200 sweeps)\n", 0), 0u) << text;
  EXPECT_NE(text.find("run: 100 % (200/200 sweeps)\n"), std::string::npos) << text;
}

TEST(ProgressBar, ElsewhereJumpsPrintTheLatestTenthOnceAndShortWorkEnds) {
  char* buffer = nullptr;
  size_t size = 0;
  std::FILE* out = open_memstream(&buffer, &size);
  {
    ProgressBar bar("sim", "sweeps", out, false);
    for (size_t done : {0, 7, 35, 36, 90, 100}) bar(done, 100);  // the simulator reports every 200 ms
  }
  std::fclose(out);
  EXPECT_EQ(std::string(buffer, size), "sim: 30 % (35/100 sweeps)\nsim: 90 % (90/100 sweeps)\nsim: 100 % (100/100 sweeps)\n");
  std::free(buffer);
  EXPECT_EQ(written(false, 2), "run: 50 % (1/2 sweeps)\nrun: 100 % (2/2 sweeps)\n");
}

TEST(ProgressBar, AsksTheStreamWhetherItIsATerminal) {
  std::FILE* file = std::tmpfile();  // a file is never a terminal
  ProgressBar bar("run", "sweeps", file);
  bar(1, 1);
  std::rewind(file);
  char line[64] = {};
  ASSERT_NE(std::fgets(line, sizeof line, file), nullptr);
  EXPECT_STREQ(line, "run: 100 % (1/1 sweeps)\n");
  std::fclose(file);
}

}  // namespace hdprior::app
