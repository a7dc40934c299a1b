// OSMesa: Mesa's off-screen renderer (llvmpipe), available on every machine lenslab builds on.
#include "gl/GlContext.h"

#include <glad/gl.h>
#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

namespace lenslab {
namespace {

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("OSMesa: could not create an OpenGL 4.5 core context");
    // OSMesaMakeCurrent needs a client buffer even though lenslab only draws into FBOs.
    buffer_.resize(4 * kBufferSide * kBufferSide);
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSide, kBufferSide)) {
      OSMesaDestroyContext(context_);
      throw std::runtime_error("OSMesa: could not make the context current");
    }
    try {
      loadGlFunctions(reinterpret_cast<GlProc (*)(const char*)>(&OSMesaGetProcAddress), "OSMesa");
    } catch (...) {
      OSMesaDestroyContext(context_);
      throw;
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }
  Backend backend() const override { return Backend::OSMesa; }

 private:
  static constexpr int kBufferSide = 4;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace lenslab
