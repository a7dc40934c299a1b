#include "io/Progress.h"

#include <iostream>
#include <string>
#include <unistd.h>

namespace lenslab {

bool isTerminal(std::FILE* stream) { return ::isatty(::fileno(stream)) != 0; }

void printProgress(int done, int total, double seconds, const char* unit) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  char times[96];
  if (done > 0 && done < total)
    std::snprintf(times, sizeof times, "%.1f s, %.1f s to go   ", seconds, seconds / done * (total - done));
  else
    std::snprintf(times, sizeof times, "%.1f s                 ", seconds);
  std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
            << std::string(static_cast<std::size_t>(kWidth - filled), ' ') << "] " << done << "/" << total << " " << unit
            << ", " << times << std::flush;
}

}  // namespace lenslab
