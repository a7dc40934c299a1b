#include "gl_test_context.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace lenslab::test {
namespace {

struct Shared {
  std::unique_ptr<GlContext> context;
  std::string whyNot;
  Shared() {
    try {
      context = createHeadlessContext(Backend::OSMesa);
    } catch (const std::exception& e) {
      whyNot = e.what();
    }
  }
};

Shared& shared() {
  static Shared s;
  return s;
}

}  // namespace

GlContext* sharedGlContext() { return shared().context.get(); }
const std::string& whyNoGlContext() { return shared().whyNot; }

}  // namespace lenslab::test
