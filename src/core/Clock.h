#pragma once
// Wall-clock seconds for progress lines, --stats timings and manifests (steady: never goes back).
#include <chrono>

namespace lenslab {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lenslab
