#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/error.h"
#include "engine/pipeline/constraint_colour.h"
#include "engine/pipeline/diagnostics_figure.h"
#include "synthetic_diagnostics.h"

namespace hdprior {
namespace {

using F = DiagnosticField;

size_t pixelsOf(const RgbImage& im, Rgb c) {
  size_t n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) n += im.at(x, y) == c;
  return n;
}

Rgb statusRgb(ConstraintClass c) {
  const Eigen::Vector4f v = constraintColour(c);
  return {uint8_t(std::lround(v.x() * 255)), uint8_t(std::lround(v.y() * 255)), uint8_t(std::lround(v.z() * 255))};
}

std::vector<const DiagnosticPlot*> named(const std::string& list) { return parseDiagnosticPlotList(list, "option --plots"); }

TEST(DiagnosticPlotList, KeepsTheOrderGivenAndDropsRepeats) {
  const auto plots = named("chi2,score,chi2");
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_STREQ(plots[0]->name, "chi2");
  EXPECT_STREQ(plots[1]->name, "score");
}

TEST(DiagnosticPlotList, UnknownOrEmptyNamesAreErrorsListingThePlots) {
  try {
    named("score,clouds");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "option --plots");
    EXPECT_NE(e.reason().find("unknown plot 'clouds'"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("sigma_lateral"), std::string::npos) << e.what();
  }
  EXPECT_THROW(named("score,,chi2"), Error);
  EXPECT_THROW(named(""), Error);
}

TEST(DiagnosticsFigure, DefaultPlotsAreThoseWithAValue) {
  std::vector<DiagnosticsRun> runs{{"a", test::syntheticDiagnostics(20)}};
  EXPECT_EQ(plotsWithValues(runs).size(), diagnosticPlots().size());
  for (KeyframeDiagnostic& d : runs[0].rows) d[F::AteAlong] = d[F::AteLateral] = std::numeric_limits<double>::quiet_NaN();
  const auto plots = plotsWithValues(runs);
  EXPECT_EQ(plots.size(), diagnosticPlots().size() - 2);
  for (const DiagnosticPlot* p : plots) EXPECT_NE(std::string(p->name).rfind("ate_", 0), 0u) << p->name;
}

TEST(DiagnosticsFigure, OnePanelPerPlotAtTheGivenWidth) {
  const std::vector<DiagnosticsRun> runs{{"a", test::syntheticDiagnostics(30)}};
  const RgbImage two = drawDiagnosticsFigure(runs, named("score,chi2"), {.width = 900, .panelHeight = 120});
  const RgbImage three = drawDiagnosticsFigure(runs, named("score,chi2,inliers"), {.width = 900, .panelHeight = 120});
  EXPECT_EQ(two.width, 900);
  EXPECT_GT(three.height - two.height, 120);
  EXPECT_LT(three.height - two.height, 200);
}

// Markers take the keyframe's status colour (the one palette, constraint_colour.h); the gate is red.
TEST(DiagnosticsFigure, MarkersInStatusColoursAndTheGateInRed) {
  const std::vector<DiagnosticsRun> runs{{"a", test::syntheticDiagnostics(30)}};
  const RgbImage chi2 = drawDiagnosticsFigure(runs, named("chi2"));
  const RgbImage inliers = drawDiagnosticsFigure(runs, named("inliers"));
  // The header's status legend has a disc of each colour; the panel adds its markers.
  const RgbImage none = drawDiagnosticsFigure(runs, {});
  for (ConstraintClass c : {ConstraintClass::Full, ConstraintClass::Partial, ConstraintClass::Gated, ConstraintClass::Rejected})
    EXPECT_GT(pixelsOf(inliers, statusRgb(c)), pixelsOf(none, statusRgb(c)) + 10) << kConstraintClassNames[size_t(c)];
  // No chi2 for a rejected match: no red marker beyond the legend's.
  EXPECT_EQ(pixelsOf(chi2, statusRgb(ConstraintClass::Rejected)), pixelsOf(none, statusRgb(ConstraintClass::Rejected)));
  EXPECT_GT(pixelsOf(chi2, kDiagnosticsThresholdColour), 500u);
  EXPECT_EQ(pixelsOf(inliers, kDiagnosticsThresholdColour), 0u);
}

// The line breaks where a value is missing: two values with a gap between them draw no line.
TEST(DiagnosticsFigure, LinesBreakAtMissingValues) {
  std::vector<KeyframeDiagnostic> rows = test::syntheticDiagnostics(3);
  for (KeyframeDiagnostic& d : rows) d[F::ScorePerPoint] = 1.0;
  const Rgb line = diagnosticsLineColour(0, 0);
  const size_t whole = pixelsOf(drawDiagnosticsFigure({{"a", rows}}, named("score")), line);
  rows[1][F::ScorePerPoint] = std::numeric_limits<double>::quiet_NaN();
  const size_t broken = pixelsOf(drawDiagnosticsFigure({{"a", rows}}, named("score")), line);
  EXPECT_GT(whole, 1000u);
  EXPECT_LT(broken, whole / 10);
}

TEST(DiagnosticsFigure, ASecondRunIsASecondLineInItsOwnColour) {
  const std::vector<DiagnosticsRun> one{{"a", test::syntheticDiagnostics(30)}};
  const std::vector<DiagnosticsRun> two{{"a", test::syntheticDiagnostics(30)}, {"b", test::syntheticDiagnostics(30, 1.0)}};
  EXPECT_NE(diagnosticsLineColour(0, 0), diagnosticsLineColour(1, 0));
  EXPECT_EQ(pixelsOf(drawDiagnosticsFigure(one, named("score")), diagnosticsLineColour(1, 0)), 0u);
  EXPECT_GT(pixelsOf(drawDiagnosticsFigure(two, named("score")), diagnosticsLineColour(1, 0)), 500u);
}

TEST(DiagnosticsFigure, APlotWithoutValuesIsAnEmptyPanel) {
  std::vector<KeyframeDiagnostic> rows = test::syntheticDiagnostics(10);
  for (KeyframeDiagnostic& d : rows) d[F::AteAlong] = std::numeric_limits<double>::quiet_NaN();
  const RgbImage im = drawDiagnosticsFigure({{"a", rows}}, named("ate_along"));
  EXPECT_EQ(pixelsOf(im, diagnosticsLineColour(0, 0)), 0u);
}

}  // namespace
}  // namespace hdprior
