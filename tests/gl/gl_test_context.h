#pragma once
// One headless OSMesa context shared by every GL test in the process (Magnum's GLTest idea):
// made on first use; tests skip cleanly when none can be made.
#include "gl/GlContext.h"

#include <gtest/gtest.h>

namespace lenslab::test {

// The shared context, or nullptr (with the reason in `whyNot`) when OSMesa cannot give 4.5 core.
GlContext* sharedGlContext();
const std::string& whyNoGlContext();

}  // namespace lenslab::test

#define LENSLAB_REQUIRE_GL()                                                          \
  do {                                                                               \
    if (!::lenslab::test::sharedGlContext())                                         \
      GTEST_SKIP() << "no OpenGL 4.5 context: " << ::lenslab::test::whyNoGlContext(); \
  } while (0)
