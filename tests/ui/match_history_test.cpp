#include <gtest/gtest.h>

#include "ui/match_history.h"

namespace hdprior::test {
namespace {

KeyframeInspection inspected(size_t keyframe, MatchStatus status, double score) {
  KeyframeInspection k;
  k.keyframe = keyframe;
  k.match.status = status;
  k.match.score = score;
  k.match.information = Eigen::Matrix3d::Identity() * 100.0;
  k.truth = Eigen::Vector3d(1.0, 2.0, 0.0);
  k.match.estimate = Eigen::Vector3d(1.0, 2.5, 0.0);
  return k;
}

// Each row says what changed since the row before; its parameters are kept to restore.
TEST(MatchHistory, EachRowSaysWhatChangedAndWhatCameOut) {
  ui::MatchHistory h;
  Config c = defaultConfig();
  h.add(c, Eigen::Vector3d::Zero(), inspected(3, MatchStatus::Accepted, 120.0));
  c.match.outlierRatio = 0.3;
  h.add(c, Eigen::Vector3d(1.0, 0.0, 0.0), inspected(3, MatchStatus::Accepted, 110.0));
  h.add(c, Eigen::Vector3d(1.0, 0.0, 0.0), inspected(4, MatchStatus::Rejected, 10.0));
  h.add(c, Eigen::Vector3d(1.0, 0.0, 0.0), inspected(4, MatchStatus::Rejected, 10.0));
  const auto& rows = h.rows();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].changes, std::vector<std::string>{"first match"});
  ASSERT_EQ(rows[1].changes.size(), 2u);
  EXPECT_EQ(rows[1].changes[0].rfind("start offset (0.00, 0.00, 0.0 deg) -> (1.00, 0.00, 0.0 deg)", 0), 0u) << rows[1].changes[0];
  EXPECT_EQ(rows[1].changes[1].rfind("match.outlier_ratio ", 0), 0u) << rows[1].changes[1];
  EXPECT_EQ(rows[2].changes, std::vector<std::string>{"keyframe 3 -> 4"});
  EXPECT_EQ(rows[3].changes, std::vector<std::string>{"no change"});
  EXPECT_EQ(rows[1].config.match.outlierRatio, 0.3);
  EXPECT_EQ(rows[0].config.match.outlierRatio, defaultConfig().match.outlierRatio);
  EXPECT_EQ(rows[1].score, 110.0);
  ASSERT_TRUE(rows[0].error.has_value());
  EXPECT_NEAR(rows[0].error->y(), 0.5, 1e-12);  // 0.5 m to the left of the truth's heading
  EXPECT_EQ(rows[0].constraint, "full");
  EXPECT_EQ(rows[2].constraint.rfind("rejected", 0), 0u) << rows[2].constraint;
}

}  // namespace
}  // namespace hdprior::test
