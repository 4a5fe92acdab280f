#include <gtest/gtest.h>

#include <string>

#include "engine/error.h"
#include "ui/view_script.h"

namespace hdprior::test {
namespace {

TEST(ViewScript, ParsesCommandsSkippingCommentsAndBlankLines) {
  const auto commands = ui::parseViewScript(
      "# a script\nframe 0\n\nstep -2   # back\nlayer sweep toggle\nopacity ground 0.5\nplay max\nview top\n"
      "wait 3\nscreenshot out.png\nexit\n",
      "s.txt");
  ASSERT_EQ(commands.size(), 9u);
  EXPECT_EQ(commands[1].verb, "step");
  EXPECT_EQ(commands[1].args, (std::vector<std::string>{"-2"}));
  EXPECT_EQ(commands[1].line, 4);
  EXPECT_EQ(commands[8].verb, "exit");
}

TEST(ViewScript, ParsesTheBenchCommands) {
  const auto commands =
      ui::parseViewScript("run\nstep-keyframe\nkeyframe 3\nmatch\noffset 0.5 -1 2.5\noptimize\ntab PGO\nreport\n", "s.txt");
  ASSERT_EQ(commands.size(), 8u);
  EXPECT_EQ(commands[2].args, std::vector<std::string>{"3"});
  EXPECT_EQ(commands[4].args, (std::vector<std::string>{"0.5", "-1", "2.5"}));
  EXPECT_EQ(commands[6].args, std::vector<std::string>{"PGO"});
}

TEST(ViewScript, ParsesTheOdometryFileCommands) {
  const auto commands =
      ui::parseViewScript("odometry a.tum\nodometry b.txt kitti\nodometry c.txt tum city\nuse-odometry builtin\n", "s.txt");
  ASSERT_EQ(commands.size(), 4u);
  EXPECT_EQ(commands[0].args, std::vector<std::string>{"a.tum"});
  EXPECT_EQ(commands[2].args, (std::vector<std::string>{"c.txt", "tum", "city"}));
  EXPECT_EQ(commands[3].args, std::vector<std::string>{"builtin"});
}

TEST(ViewScript, ParsesTheDebuggingBenchCommands) {
  const auto commands = ui::parseViewScript(
      "plot chi2 on\nevents\nnext-event\nprev-event\nbookmark kerb looks off\ncompare b.json\nmeasure 1 2 3.5 -4\n"
      "measure match\npick 10 -2.5\nsave-session s.json\nload-session s.json\ntab Compare\nground-labels flow_labels.feather 0\n",
      "s.txt");
  ASSERT_EQ(commands.size(), 13u);
  EXPECT_EQ(commands[12].args, (std::vector<std::string>{"flow_labels.feather", "0"}));
  EXPECT_EQ(commands[4].args, (std::vector<std::string>{"kerb", "looks", "off"}));
  EXPECT_EQ(commands[6].args, (std::vector<std::string>{"1", "2", "3.5", "-4"}));
  EXPECT_EQ(commands[7].args, std::vector<std::string>{"match"});
  EXPECT_EQ(commands[8].args, (std::vector<std::string>{"10", "-2.5"}));
}

TEST(ViewScript, RejectsBadLinesNamingTheLine) {
  const std::pair<const char*, const char*> bad[] = {
      {"frame 0\nfly away\n", "line 2: unknown command 'fly'"},
      {"frame -1\n", "line 1"},
      {"step\n", "takes 1"},
      {"layer clouds on\n", "unknown layer 'clouds'"},
      {"layer sweep maybe\n", "on, off or toggle"},
      {"opacity sweep 1.5\n", "0..1"},
      {"play 3x\n", "1x, 2x, 5x or max"},
      {"view side\n", "top or orbit"},
      {"wait 2 3\n", "takes 1"},
      {"run now\n", "takes 0"},
      {"keyframe -2\n", "non-negative integer"},
      {"offset 1 x 2\n", "three numbers"},
      {"offset 1 2\n", "takes 3"},
      {"tab Plots\n", "Pipeline, NDT, PGO, Keyframe, Events, Compare or Export"},
      {"plot speed on\n", "unknown plot 'speed'"},
      {"plot score maybe\n", "on or off"},
      {"compare\n", "takes 1"},
      {"measure 1 2 3\n", "four numbers"},
      {"measure 1 2 x 4\n", "four numbers"},
      {"measure truth\n", "or 'match'"},
      {"pick 1\n", "takes 2"},
      {"pick 1 y\n", "two numbers"},
      {"save-session\n", "takes 1"},
      {"load-session a b\n", "takes 1"},
      {"odometry\n", "takes 1 to 3"},
      {"odometry a.tum tum first x\n", "takes 1 to 3"},
      {"odometry a.tum csv\n", "auto, tum or kitti"},
      {"odometry a.tum tum map\n", "first or city"},
      {"use-odometry maybe\n", "file or builtin"},
      {"ground-labels labels.feather\n", "takes 2"},
      {"ground-labels labels.feather -1\n", "a non-negative frame"},
  };
  for (const auto& [text, message] : bad) {
    try {
      ui::parseViewScript(text, "s.txt");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.txt"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace hdprior::test
