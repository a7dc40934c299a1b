#include "io/Progress.h"

#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace lenslab {
namespace {

// A bar is redrawn at most this often: a ray cast reports every band of 16 rows.
constexpr double kBarRedrawSeconds = 0.1;

std::string figures(std::int64_t done, std::int64_t total, std::string_view unit, double seconds) {
  char text[160];
  if (done > 0 && done < total)
    std::snprintf(text, sizeof text, "%lld/%lld %.*s, %.1f s, %.1f s to go", static_cast<long long>(done),
                  static_cast<long long>(total), static_cast<int>(unit.size()), unit.data(), seconds,
                  seconds / static_cast<double>(done) * static_cast<double>(total - done));
  else
    std::snprintf(text, sizeof text, "%lld/%lld %.*s, %.1f s", static_cast<long long>(done),
                  static_cast<long long>(total), static_cast<int>(unit.size()), unit.data(), seconds);
  return text;
}

bool isTerminal(std::FILE* stream) { return ::isatty(::fileno(stream)) != 0; }

}  // namespace

double progressIntervalSeconds(double defaultSeconds) {
  const char* text = std::getenv("LENSLAB_PROGRESS_SECONDS");
  if (!text || !*text) return defaultSeconds;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (*end != '\0' || !(seconds >= 0.0 && seconds <= 86400.0))
    throw InputError(cat("LENSLAB_PROGRESS_SECONDS=", text,
                         ": give the seconds between progress lines, a number from 0 "
                         "to 86400 (default ",
                         kProgressIntervalSeconds, "; 0 = a line at every step)"));
  return seconds;
}

std::string progressLine(std::string_view label, std::int64_t done, std::int64_t total, std::string_view unit,
                         double seconds, std::string_view detail) {
  std::string line = cat("lenslab: ", label, ": ", figures(done, total, unit, seconds));
  if (!detail.empty()) line += cat("; ", detail);
  return line;
}

ProgressReporter::ProgressReporter(std::string label, std::string unit, bool quiet, double defaultIntervalSeconds)
    : ProgressReporter(std::move(label), std::move(unit),
                       quiet                ? Style::Silent
                       : isTerminal(stderr) ? Style::Bar
                                            : Style::Lines,
                       quiet ? 0.0 : progressIntervalSeconds(defaultIntervalSeconds), std::cerr,
                       [start = std::chrono::steady_clock::now()] { return secondsSince(start); }) {}

ProgressReporter::ProgressReporter(std::string label, std::string unit, Style style, double intervalSeconds,
                                   std::ostream& out, std::function<double()> clock)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      style_(style),
      interval_(intervalSeconds),
      out_(out),
      clock_(std::move(clock)) {
  start_ = clock_();
  lastLine_ = start_;
}

ProgressReporter::~ProgressReporter() {
  // Cut short (an exception on the way): end the bar's line, so that the error starts its own.
  if (barShown_) out_ << "\n" << std::flush;
}

double ProgressReporter::elapsed() const { return clock_() - start_; }

void ProgressReporter::update(std::int64_t done, std::int64_t total, std::string_view detail) {
  done_ = done;
  total_ = total;
  detail_ = detail;
  if (style_ == Style::Silent) return;
  const double now = clock_();
  if (style_ == Style::Bar) {
    if (done < total && wroteAny_ && now - lastLine_ < kBarRedrawSeconds) return;
    constexpr int kWidth = 30;
    const int filled = total > 0 ? static_cast<int>(std::min<std::int64_t>(done, total) * kWidth / total) : kWidth;
    const std::string bar = cat("[", std::string(static_cast<std::size_t>(filled), '#'),
                                std::string(static_cast<std::size_t>(kWidth - filled), ' '), "] ",
                                figures(done, total, unit_, now - start_), detail.empty() ? "" : ", ", detail);
    // Spaces wipe what a longer bar before it left.
    out_ << "\r" << bar << std::string(barLength_ > bar.size() ? barLength_ - bar.size() : 0, ' ') << std::flush;
    barLength_ = bar.size();
    lastLine_ = now;
    wroteAny_ = barShown_ = true;
    return;
  }
  // Lines: the first when the interval has passed since the start, then one an interval.
  if (done >= total || now - lastLine_ < interval_) return;
  out_ << progressLine(label_, done, total, unit_, now - start_, detail) << "\n" << std::flush;
  lastLine_ = now;
  wroteAny_ = true;
}

void ProgressReporter::note(std::string_view line) {
  if (barShown_) {
    out_ << "\r" << line << std::string(barLength_ > line.size() ? barLength_ - line.size() : 0, ' ') << "\n"
         << std::flush;
    barShown_ = false;
    barLength_ = 0;
    lastLine_ = -1e300;  // the bar comes back at the next update
  } else {
    out_ << line << "\n" << std::flush;
  }
}

void ProgressReporter::finish() {
  if (style_ == Style::Silent || !wroteAny_) return;
  if (style_ == Style::Bar) {
    if (barShown_) out_ << "\n" << std::flush;
    barShown_ = false;
  } else if (!finished_) {
    out_ << progressLine(label_, done_, total_, unit_, elapsed(), detail_) << "\n" << std::flush;
  }
  finished_ = true;
}

}  // namespace lenslab
