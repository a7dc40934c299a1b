#pragma once
// docs/stability.md holds lenslab_stability's table between two markers. These read that table
// back and compare a documented row with a run's, so that `lenslab_stability --check-doc` can
// tell whether the page still describes what the program measures.
//
// A row is found by its identity (group, case, bound: text that does not depend on the machine)
// and its measured cell is compared with a tolerance, never digit for digit: llvmpipe and Embree
// pick their SIMD code paths (SSE2 … AVX-512, with or without FMA) by CPU, and the order and
// fusing of float operations move the last digits of a figure from one CPU to another.
//
// The measured cell is split into its words and its figures:
//  - "X dB" and "identical" (X = infinity) are PSNR figures: -20·log10(RMS error), colours in
//    [0, 1]. They compare as RMS errors, within kRelativeTolerance of the larger one or within
//    kRoundingFloor of each other (see those constants for why).
//  - A bare number compares the same way when the row's figure is a colour difference
//    (BareNumbers::ColourDifference); otherwise (counts, percentages, numbers quoted in a refusal)
//    it is part of the words. Those come from the program's own double arithmetic, not from a
//    SIMD path, and must match exactly.
//  - The words ("raster", "finite", "refused in one line", "100 %", "(fails)", ...) must match
//    exactly.
#include <string>
#include <vector>

namespace lenslab::stability {

// The markers around the table in the doc.
inline constexpr const char* kTableBegin = "<!-- stability-table:begin -->";
inline constexpr const char* kTableEnd = "<!-- stability-table:end -->";

// Below this RMS (or absolute) colour difference two figures both say "equal but for float
// rounding" (PSNR ≥ 100 dB): an image accumulated from up to 64 float views carries rounding of
// this order (about 170 float steps at 0.5), and which pixels round one step apart depends on the
// SIMD path. Measured (tests/stability/simd_spread.sh): figures above 100 dB moved by up to 27 dB
// between Embree's SSE2 and AVX-512 kernels (RMS 7.7e-9 … 1.6e-7) and by up to 3.6 dB between
// llvmpipe's code paths (105.4 … 109.0 dB, RMS 5.4e-6 … 3.5e-6), all within 1e-5 of each other.
inline constexpr double kRoundingFloor = 1e-5;

// Above the floor, figures compare within 20 % of the larger (about 1.9 dB of PSNR). Measured: the
// forced SIMD paths moved figures below 100 dB by up to 0.3 dB (26.4 → 26.1 dB, raster vs ray cast,
// llvmpipe without SSE), 3.5 % in RMS, on one CPU; on an AMD EPYC, Embree's SSE2 path (isa=sse2)
// against its native one moves the box corner at a field of view of 1e-5 rad (4 views against
// 4 spp, a handful of edge pixels) from 44.1 to 42.7 dB, 15 % in RMS. 20 % holds both, and still
// fails a figure that has really changed (two dB or more).
inline constexpr double kRelativeTolerance = 0.20;

enum class BareNumbers {
  Exact,            // counts, percentages, numbers quoted in a refusal: part of the words
  ColourDifference  // the row's figure is a colour difference (e.g. largest abs(mean − exact))
};

struct TableRow {
  std::string group;  // carried down from the row that names it
  std::string input;  // the case
  std::string bound;
  std::string measured;
};

// A cell as the table writes it ('|' escaped) and back.
std::string escapeCell(const std::string& text);
std::string unescapeCell(const std::string& cell);

// The rows of the Markdown table between kTableBegin and kTableEnd in `doc` (header and separator
// left out). Throws std::runtime_error naming `docName` when the markers are missing.
std::vector<TableRow> parseDocTable(const std::string& doc, const std::string& docName);

// Why `measured` is not `documented` within the tolerances above, in one line; empty when it is.
std::string cellDifference(const std::string& documented, const std::string& measured, BareNumbers bare);

}  // namespace lenslab::stability
