// The doc check of lenslab_stability on hand-made cells: what moves within tolerance passes, what
// moves beyond it or changes its words fails.
#include "TableCheck.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace lenslab::stability {
namespace {

bool same(const std::string& documented, const std::string& measured, BareNumbers bare = BareNumbers::Exact) {
  return cellDifference(documented, measured, bare).empty();
}

TEST(TableCheck, PsnrFiguresCompareWithinAboutTwoDecibels) {
  EXPECT_TRUE(same("finite, 26.4 dB", "finite, 26.4 dB"));
  EXPECT_TRUE(same("finite, 26.4 dB", "finite, 26.1 dB"));  // llvmpipe without SSE
  EXPECT_TRUE(same("44.1 dB", "42.7 dB"));                  // Embree's SSE2 path on an AMD EPYC
  EXPECT_TRUE(same("33.5 dB", "35.2 dB"));
  EXPECT_FALSE(same("33.5 dB", "35.6 dB"));
  EXPECT_FALSE(same("33.5 dB", "31.4 dB"));
  EXPECT_FALSE(same("76.2 dB; 42.4 dB", "76.2 dB; 40.0 dB"));
  EXPECT_TRUE(same("76.2 dB; 42.4 dB", "76.9 dB; 42.0 dB"));
}

TEST(TableCheck, FiguresAtFloatRoundingAgreeWhateverTheirDecibels) {
  // Both above 100 dB (RMS below 1e-5): rounding, which the SIMD path decides.
  EXPECT_TRUE(same("raster 152.0 dB, ray cast 162.3 dB", "raster 151.6 dB, ray cast 135.8 dB"));
  EXPECT_TRUE(same("raster identical, ray cast identical", "raster 152.0 dB, ray cast identical"));
  EXPECT_TRUE(same("raster 105.7 dB, ray cast 116.0 dB", "raster 98.0 dB, ray cast 116.0 dB"));
  // A figure that leaves the rounding floor has changed.
  EXPECT_FALSE(same("raster identical, ray cast identical", "raster 80.0 dB, ray cast identical"));
  EXPECT_FALSE(same("raster 105.7 dB, ray cast 116.0 dB", "raster 90.0 dB, ray cast 116.0 dB"));
}

TEST(TableCheck, WordsMustMatchExactly) {
  EXPECT_FALSE(same("finite, 26.4 dB", "NOT FINITE, 26.4 dB"));
  EXPECT_FALSE(same("33.5 dB", "33.5 dB **(fails)**"));
  EXPECT_FALSE(same("100 %, 100 % at the worst depth", "99.6 %, 100 % at the worst depth"));
  EXPECT_FALSE(same("266660000 of 266660000 pixels, finite", "266659999 of 266660000 pixels, finite"));
  const std::string refusal = "refused: camera: focus_distance is 0.035; it must be beyond";
  EXPECT_TRUE(same(refusal, refusal));
  EXPECT_FALSE(same(refusal, "refused: camera: focus_distance is 0.036; it must be beyond"));
  // "12.0 dBx" is a word, not a PSNR figure.
  EXPECT_FALSE(same("12.0 dBx", "12.1 dBx"));
}

TEST(TableCheck, ColourDifferencesCompareRelativelyAboveTheRoundingFloor) {
  const BareNumbers c = BareNumbers::ColourDifference;
  EXPECT_TRUE(same("0.0055", "0.00548", c));  // the last digit, from one CPU to another
  EXPECT_TRUE(same("0.0055", "0.006", c));
  EXPECT_FALSE(same("0.0055", "0.0070", c));
  EXPECT_TRUE(same("5.36e-07", "3.1e-06", c));  // both float rounding
  EXPECT_FALSE(same("5.36e-07", "2.5e-05", c));
  EXPECT_TRUE(same("4.92e-05", "5.2e-05", c));
  EXPECT_FALSE(same("4.92e-05", "7e-05", c));
  EXPECT_TRUE(same("inf", "inf", c));
  EXPECT_FALSE(same("inf", "0.0055", c));
  EXPECT_FALSE(same("NaN", "0.0055", c));
  // Without ColourDifference a bare number is a word.
  EXPECT_FALSE(same("0.0055", "0.00548"));
}

TEST(TableCheck, TheDifferenceSaysWhatMoved) {
  const std::string why =
      cellDifference("raster 33.5 dB, ray cast 40.0 dB", "raster 33.5 dB, ray cast 36.0 dB", BareNumbers::Exact);
  EXPECT_NE(why.find("40.0 dB"), std::string::npos) << why;
  EXPECT_NE(why.find("36.0 dB"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

TEST(TableCheck, ReadsTheTableBetweenItsMarkers) {
  const std::string doc =
      "# page\n\n| not | the | table | row |\n<!-- stability-table:begin -->\n"
      "| | case | bound | measured |\n|---|---|---|---|\n"
      "| focus | f/2.8 | ≥ 40 dB | raster 105.7 dB |\n"
      "|  | f \\| 2 | refused in one line | a \\| b |\n"
      "| depth | z | 100 % | 100 % |\n"
      "<!-- stability-table:end -->\n| after | the | table | row |\n";
  const std::vector<TableRow> rows = parseDocTable(doc, "page.md");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].group, "focus");
  EXPECT_EQ(rows[0].measured, "raster 105.7 dB");
  EXPECT_EQ(rows[1].group, "focus");  // carried down
  EXPECT_EQ(rows[1].input, "f | 2");
  EXPECT_EQ(rows[1].measured, "a | b");
  EXPECT_EQ(rows[2].group, "depth");
  EXPECT_EQ(unescapeCell(escapeCell("a | b")), "a | b");
  EXPECT_THROW(parseDocTable("no markers here", "page.md"), std::runtime_error);
}

}  // namespace
}  // namespace lenslab::stability
