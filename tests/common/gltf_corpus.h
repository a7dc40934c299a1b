#pragma once
// Where the external glTF corpus lies, for the suites that read it (LENSLAB_CORPUS_SUITES in
// tests/CMakeLists.txt: ctest's entry `corpus`, which ctest shows as not run when the corpus is
// absent), and the skip for a test whose file the corpus lacks.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace lenslab::test {

// The environment variable wins over the path compiled in, so a build can be pointed elsewhere.
inline std::filesystem::path corpusDirectory() {
  if (const char* env = std::getenv("LENSLAB_GLTF_CORPUS_DIR"); env && *env) return env;
  return LENSLAB_GLTF_CORPUS_DIR;
}

inline std::filesystem::path samplesDirectory() { return corpusDirectory() / "samples"; }
inline std::filesystem::path invalidDirectory() { return corpusDirectory() / "invalid"; }

}  // namespace lenslab::test

#define SKIP_UNLESS_EXISTS(path)                                                                           \
  do {                                                                                                     \
    if (!std::filesystem::exists(path)) GTEST_SKIP() << (path) << " is absent (the external glTF corpus)"; \
  } while (false)
