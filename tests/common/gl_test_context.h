#pragma once
// One headless OSMesa context shared by every GL test in the process (Magnum's GLTest idea):
// made on first use; a test that needs it fails when none can be made.
#include "gl/GlContext.h"

#include <gtest/gtest.h>

namespace lenslab::test {

// The shared context, or nullptr (with the reason in `whyNot`) when OSMesa cannot give 4.5 core.
GlContext* sharedGlContext();
const std::string& whyNoGlContext();

}  // namespace lenslab::test

// A failure, not a skip: OSMesa is one of lenslab's dependencies (tools/install-deps.sh), so a
// machine that cannot give a context has a broken install, and a skipped GL suite would let ctest
// report "100% passed" over tests that never ran.
#define LENSLAB_REQUIRE_GL()                                                          \
  do {                                                                                \
    if (!::lenslab::test::sharedGlContext())                                          \
      GTEST_FAIL() << "no OpenGL 4.5 context: " << ::lenslab::test::whyNoGlContext(); \
  } while (0)
