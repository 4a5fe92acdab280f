#include <gtest/gtest.h>

#include "engine/eval/bitmap_font.h"
#include "engine/eval/box_plot.h"

namespace hdprior {

TEST(BoxStats, QuartilesWhiskersAndAHighOutlier) {
  const BoxStats s = boxStats({9, 1, 8, 2, 7, 3, 100, 4, 6, 5});
  EXPECT_EQ(s.count, 10u);
  EXPECT_DOUBLE_EQ(s.q1, 3.25);  // linear between order statistics: 3 + 0.25 (4 - 3)
  EXPECT_DOUBLE_EQ(s.median, 5.5);
  EXPECT_DOUBLE_EQ(s.q3, 7.75);
  EXPECT_DOUBLE_EQ(s.whiskerLow, 1.0);  // fences at 3.25 - 6.75 and 7.75 + 6.75
  EXPECT_DOUBLE_EQ(s.whiskerHigh, 9.0);
  EXPECT_EQ(s.outliers, std::vector<double>{100.0});
}

TEST(BoxStats, LowOutlierAndOddCount) {
  const BoxStats s = boxStats({12, -50, 10, 14, 11, 13});
  EXPECT_DOUBLE_EQ(s.q1, 10.25);
  EXPECT_DOUBLE_EQ(s.median, 11.5);
  EXPECT_DOUBLE_EQ(s.q3, 12.75);
  EXPECT_DOUBLE_EQ(s.whiskerLow, 10.0);
  EXPECT_DOUBLE_EQ(s.whiskerHigh, 14.0);
  EXPECT_EQ(s.outliers, std::vector<double>{-50.0});
  const BoxStats odd = boxStats({2, 4, 6, 8, 10});
  EXPECT_DOUBLE_EQ(odd.q1, 4.0);
  EXPECT_DOUBLE_EQ(odd.median, 6.0);
  EXPECT_DOUBLE_EQ(odd.q3, 8.0);
  EXPECT_TRUE(odd.outliers.empty());
}

TEST(BoxStats, DegenerateInputs) {
  EXPECT_EQ(boxStats({}).count, 0u);
  const BoxStats one = boxStats({0.3});
  EXPECT_DOUBLE_EQ(one.q1, 0.3);
  EXPECT_DOUBLE_EQ(one.q3, 0.3);
  EXPECT_DOUBLE_EQ(one.whiskerHigh, 0.3);
  EXPECT_TRUE(one.outliers.empty());
}

namespace {

const Rgb kRed{200, 30, 30}, kBlue{30, 60, 200}, kWhite{255, 255, 255};

std::vector<BoxPlotSeries> twoSeries() {
  return {{"odometry", {0.10, 0.12, 0.14, 0.16, 0.18, 0.60}, kRed}, {"priors", {0.04, 0.08, 0.12, 0.16}, kBlue}};
}

}  // namespace

TEST(BoxPlot, BoxesWhiskersAndOutliersWhereTheLayoutPutsThem) {
  const BoxPlotOptions options{.width = 640, .height = 480, .title = "ATE RMSE per log", .yTitle = "ATE RMSE (m)"};
  const auto series = twoSeries();
  const RgbImage im = drawBoxPlot(series, options);
  ASSERT_EQ(im.width, 640);
  ASSERT_EQ(im.height, 480);
  const BoxPlotLayout L = boxPlotLayout(series, options);
  ASSERT_EQ(L.centres.size(), 2u);
  EXPECT_LT(L.centres[0], L.centres[1]);
  EXPECT_GE(L.yMax, 0.60);
  EXPECT_LE(L.yMax, 0.80);

  const BoxStats a = boxStats(series[0].values), b = boxStats(series[1].values);
  const int inner = L.boxHalfWidth - 4;  // beside the jittered dots, inside the outline
  // Inside each box between the quartiles: its tint; just outside the box: not.
  EXPECT_EQ(im.at(L.centres[0] + inner, L.yPixel((a.q1 + a.median) / 2)), boxFill(kRed));
  EXPECT_EQ(im.at(L.centres[1] - inner, L.yPixel((b.median + b.q3) / 2)), boxFill(kBlue));
  EXPECT_NE(im.at(L.centres[0] + L.boxHalfWidth + 6, L.yPixel((a.q1 + a.median) / 2)), boxFill(kRed));
  // The outlier 0.60 is a dot on the box's centre line; the whisker reaches 0.18, not further.
  EXPECT_EQ(im.at(L.centres[0], L.yPixel(0.60)), kRed);
  EXPECT_EQ(im.at(L.centres[0], L.yPixel((a.whiskerHigh + a.q3) / 2)), kRed);
  EXPECT_EQ(im.at(L.centres[0], L.yPixel(0.45)), kWhite);  // between ticks
  // Nothing of the red series in the blue one's column.
  EXPECT_NE(im.at(L.centres[1], L.yPixel(0.60)), kRed);
  // Labels are drawn below the axis.
  bool ink = false;
  for (int y = L.bottom + 10; y < im.height; ++y) ink |= im.at(L.centres[0], y) != kWhite || im.at(L.centres[0] - 20, y) != kWhite;
  EXPECT_TRUE(ink);
}

TEST(BoxPlot, Deterministic) {
  const RgbImage a = drawBoxPlot(twoSeries(), {}), b = drawBoxPlot(twoSeries(), {});
  EXPECT_EQ(a.rgb, b.rgb);
}

TEST(BitmapFont, GlyphsTextWidthAndDirection) {
  EXPECT_NE(glyph('a'), glyph('?'));
  EXPECT_NE(glyph('A'), glyph('a'));
  EXPECT_EQ(glyph('~'), glyph('?'));  // not in the font
  EXPECT_EQ(textWidth("0.25", 2), (4 * kGlyphAdvance - 1) * 2);
  EXPECT_EQ(textWidth("", 2), 0);

  // 'I' horizontally: its top bar spans columns 1-3 of row 0; upwards, the same bar becomes a column.
  RgbImage h(20, 20, kWhite), u(20, 20, kWhite);
  drawText(h, 2, 2, "I", 1, kRed);
  EXPECT_EQ(h.at(3, 2), kRed);
  EXPECT_EQ(h.at(2, 2), kWhite);
  EXPECT_EQ(h.at(4, 5), kRed);  // the stem
  drawText(u, 2, 17, "I", 1, kRed, TextDirection::Upwards);
  EXPECT_EQ(u.at(2, 17 - 2), kRed);  // row 0, column 1 -> one pixel right of the left edge, 2 up
  EXPECT_EQ(u.at(2, 17 - 1), kWhite);
  EXPECT_EQ(u.at(5, 17 - 3), kRed);  // the stem runs horizontally now
}

}  // namespace hdprior
