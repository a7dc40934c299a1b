#include "io/Progress.h"

#include "core/Text.h"

#include <iostream>
#include <string>
#include <unistd.h>

namespace lenslab {

bool isTerminal(std::FILE* stream) { return ::isatty(::fileno(stream)) != 0; }

void printProgress(int done, int total, double seconds) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
            << std::string(static_cast<std::size_t>(kWidth - filled), ' ') << "] " << done << "/" << total
            << " samples, " << cat(seconds) << " s" << std::flush;
}

}  // namespace lenslab
