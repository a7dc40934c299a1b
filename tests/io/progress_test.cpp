// Progress reporting (io/Progress.h): the lines a log gets, with a clock the test moves.
#include "core/Error.h"
#include "io/Progress.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace lenslab {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(Progress, LineNamesTheWorkTheCountsTheTimeAndTheTimeToGo) {
  EXPECT_EQ(progressLine("render", 37, 98, "samples", 12.3), "lenslab: render: 37/98 samples, 12.3 s, 20.3 s to go");
  EXPECT_EQ(progressLine("raycast", 98, 98, "rows", 30.25), "lenslab: raycast: 98/98 rows, 30.2 s");
  EXPECT_EQ(progressLine("render", 0, 98, "samples", 4.0, "inverse lens table, 16/960 rows"),
            "lenslab: render: 0/98 samples, 4.0 s; inverse lens table, 16/960 rows");
}

TEST(Progress, LinesComeOneAnIntervalAndTheLastAtFinish) {
  std::ostringstream out;
  double now = 100.0;
  ProgressReporter p("render", "samples", ProgressReporter::Style::Lines, 5.0, out, [&now] { return now; });
  for (int done = 1; done <= 20; ++done) {
    now += 1.0;  // a sample a second
    p.update(done, 20);
  }
  p.finish();
  const std::vector<std::string> lines = linesOf(out.str());
  // At 5, 10 and 15 s (not at 20: the last line is finish's), then the last.
  ASSERT_EQ(lines.size(), 4u) << out.str();
  EXPECT_EQ(lines[0], "lenslab: render: 5/20 samples, 5.0 s, 15.0 s to go");
  EXPECT_EQ(lines[1], "lenslab: render: 10/20 samples, 10.0 s, 10.0 s to go");
  EXPECT_EQ(lines[2], "lenslab: render: 15/20 samples, 15.0 s, 5.0 s to go");
  EXPECT_EQ(lines[3], "lenslab: render: 20/20 samples, 20.0 s");
}

TEST(Progress, WorkShorterThanTheIntervalWritesNothing) {
  std::ostringstream out;
  double now = 0.0;
  ProgressReporter p("raycast", "rows", ProgressReporter::Style::Lines, 5.0, out, [&now] { return now; });
  for (int done = 16; done <= 64; done += 16) {
    now += 1.0;
    p.update(done, 64);
  }
  p.finish();
  EXPECT_EQ(out.str(), "");
}

TEST(Progress, TheFinalLineCountsTimeAfterTheLastUnit) {
  std::ostringstream out;
  double now = 0.0;
  ProgressReporter p("render", "samples", ProgressReporter::Style::Lines, 0.0, out, [&now] { return now; });
  now = 1.0;
  p.update(1, 2);
  now = 2.0;
  p.update(2, 2, "writing out.png");  // the last unit: no line yet
  now = 9.0;                          // the file takes 7 s
  p.update(2, 2);
  p.finish();
  p.finish();  // once
  const std::vector<std::string> lines = linesOf(out.str());
  ASSERT_EQ(lines.size(), 2u) << out.str();
  EXPECT_EQ(lines[1], "lenslab: render: 2/2 samples, 9.0 s");
}

TEST(Progress, SilentWritesNothingAndNotesGoOnTheirOwnLines) {
  std::ostringstream silent;
  ProgressReporter quiet("render", "samples", ProgressReporter::Style::Silent, 0.0, silent, [] { return 0.0; });
  quiet.update(1, 2);
  quiet.finish();
  EXPECT_EQ(silent.str(), "");

  std::ostringstream bar;
  double now = 0.0;
  ProgressReporter p("capture", "frames", ProgressReporter::Style::Bar, 5.0, bar, [&now] { return now; });
  now = 1.0;
  p.update(1, 4);
  p.note("lenslab: warning: something");
  now = 2.0;
  p.update(2, 4);
  p.finish();
  // The bar is redrawn in place (\r), the note takes its line, and the bar comes back below it.
  const std::vector<std::string> lines = linesOf(bar.str());
  ASSERT_EQ(lines.size(), 2u) << bar.str();
  EXPECT_NE(lines[0].find("\rlenslab: warning: something"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("2/4 frames, 2.0 s, 2.0 s to go"), std::string::npos) << lines[1];
}

TEST(Progress, IntervalComesFromTheEnvironmentAndBadValuesAreRefused) {
  ASSERT_EQ(::setenv("LENSLAB_PROGRESS_SECONDS", "0.5", 1), 0);
  EXPECT_EQ(progressIntervalSeconds(), 0.5);
  for (const char* bad : {"abc", "-1", "5s", "1e9", "nan"}) {
    ASSERT_EQ(::setenv("LENSLAB_PROGRESS_SECONDS", bad, 1), 0);
    EXPECT_THROW(progressIntervalSeconds(), InputError) << bad;
  }
  ASSERT_EQ(::unsetenv("LENSLAB_PROGRESS_SECONDS"), 0);
  EXPECT_EQ(progressIntervalSeconds(), 5.0);
  EXPECT_EQ(progressIntervalSeconds(0.0), 0.0);  // capture's default: a line a frame
}

}  // namespace
}  // namespace lenslab
