#pragma once
// Progress on long work, on stderr, in one of three styles chosen once per piece of work:
//   a terminal   a bar redrawn in place: "[#####     ] 12/73 frames, 30.1 s, 43.2 s to go"
//   otherwise    (a log file, a Slurm job's output) one line every few seconds, so that a log shows
//                the work is alive without a line per step:
//                  "lenslab: render: 37/98 samples, 12.3 s, 20.1 s to go"
//                nothing for work that ends within the interval, and at finish() a last line with
//                the total ("lenslab: render: 98/98 samples, 30.2 s") once any line was written.
//                The interval is LENSLAB_PROGRESS_SECONDS (default 5; 0 = a line at every update).
//   --quiet      nothing
// The time to go assumes the rest take as long each as those done so far.
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace lenslab {

constexpr double kProgressIntervalSeconds = 5.0;

// The seconds between progress lines: LENSLAB_PROGRESS_SECONDS, else `defaultSeconds`. Throws
// InputError for a value that is not a number from 0 to 86400.
double progressIntervalSeconds(double defaultSeconds = kProgressIntervalSeconds);

// "lenslab: render: 37/98 samples, 12.3 s, 20.1 s to go", with "; DETAIL" after it when given.
std::string progressLine(std::string_view label, std::int64_t done, std::int64_t total, std::string_view unit,
                         double seconds, std::string_view detail = {});

class ProgressReporter {
 public:
  enum class Style { Bar, Lines, Silent };

  // Bar on a terminal, Lines elsewhere, Silent when `quiet`; the clock starts now.
  // `label` names the work in lines ("render", "raycast", "sweep: reference"), `unit` what is
  // counted ("samples", "rows", "frames"). `defaultIntervalSeconds`: between lines unless
  // LENSLAB_PROGRESS_SECONDS says otherwise (capture: 0, a line a frame).
  ProgressReporter(std::string label, std::string unit, bool quiet,
                   double defaultIntervalSeconds = kProgressIntervalSeconds);
  // For tests: the style, the interval, where lines go and the clock (seconds, any origin).
  ProgressReporter(std::string label, std::string unit, Style style, double intervalSeconds, std::ostream& out,
                   std::function<double()> clock);
  ~ProgressReporter();  // ends a bar's line (work cut short by an error included)
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // `done` of `total` units, `detail` a short note after the figures (e.g. the estimated PSNR).
  // In Lines style the line for done = total is left to finish(), which knows the whole time
  // (work after the last unit, such as writing the file, included).
  void update(std::int64_t done, std::int64_t total, std::string_view detail = {});
  // The same figures with another note (empty: none), e.g. while the file is written.
  void setDetail(std::string_view detail) { update(done_, total_, detail); }
  // A line of its own (a warning, a phase that ended) that leaves the bar whole: on a terminal
  // it takes the bar's place and the bar is drawn again below it at the next update. Written in
  // every style, Silent included: the caller decides what --quiet hides.
  void note(std::string_view line);
  // Ends the bar's line; in Lines style writes the last line (done of total, the time taken) when
  // any line was written, so that a log does not stop at "37/98".
  void finish();

  Style style() const { return style_; }
  std::int64_t done() const { return done_; }
  std::int64_t total() const { return total_; }
  const std::string& unit() const { return unit_; }
  void setUnit(std::string unit) { unit_ = std::move(unit); }

 private:
  double elapsed() const;

  std::string label_;
  std::string unit_;
  Style style_;
  double interval_;
  std::ostream& out_;
  std::function<double()> clock_;
  double start_ = 0.0;
  double lastLine_ = 0.0;  // when the last line was written (Lines)
  bool wroteAny_ = false;  // a line or a bar was written
  bool barShown_ = false;  // a bar is on the terminal's last line
  std::size_t barLength_ = 0;
  bool finished_ = false;
  std::int64_t done_ = 0;
  std::int64_t total_ = 0;
  std::string detail_;
};

}  // namespace lenslab
