// OSMesa: Mesa's off-screen renderer (llvmpipe), available on every machine lenslab builds on.
// The library is opened at run time rather than linked: it brings LLVM (over 100 MB) with it, and
// a binary that renders through EGL on a GPU server should not need it.
#include "gl/GlContext.h"

#include "core/MemoryLimit.h"

#include <glad/gl.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <string>
#include <vector>

namespace lenslab {
namespace {

struct OsmesaLibrary {
  void* handle = nullptr;
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;

  std::string error;  // dlopen's reason, when it failed

  OsmesaLibrary() {
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
      if ((handle = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
      if (error.empty())
        if (const char* why = dlerror()) error = why;
    }
    if (!handle) return;
    createContextAttribs =
        reinterpret_cast<decltype(createContextAttribs)>(dlsym(handle, "OSMesaCreateContextAttribs"));
    makeCurrent = reinterpret_cast<decltype(makeCurrent)>(dlsym(handle, "OSMesaMakeCurrent"));
    destroyContext = reinterpret_cast<decltype(destroyContext)>(dlsym(handle, "OSMesaDestroyContext"));
    getProcAddress = reinterpret_cast<decltype(getProcAddress)>(dlsym(handle, "OSMesaGetProcAddress"));
  }
  bool ok() const { return createContextAttribs && makeCurrent && destroyContext && getProcAddress; }
};

// llvmpipe's rendering threads: LP_NUM_THREADS, else one per core (at most 32, Mesa's cap).
unsigned llvmpipeThreads() {
  if (const char* v = std::getenv("LP_NUM_THREADS"); v && *v)
    return static_cast<unsigned>(std::clamp(std::atoi(v), 0, 32));
  return std::min(std::max(std::thread::hardware_concurrency(), 1u), 32u);
}

// Loaded once, kept for the process (contexts come and go; the library stays).
const OsmesaLibrary& osmesa() {
  static const OsmesaLibrary library;
  return library;
}

// glad calls this without a user pointer, so it goes through the process-wide library.
GlProc osmesaProc(const char* name) { return reinterpret_cast<GlProc>(osmesa().getProcAddress(name)); }

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() {
    // Under a low ulimit -v, llvmpipe fails to load, to make a context, or crashes compiling a
    // shader: refused here in one line instead.
    requireAddressSpace(addressSpaceForLlvmpipeBytes(llvmpipeThreads()), "OpenGL through OSMesa (llvmpipe)");
    if (!osmesa().ok()) {
      // Only a missing library wants installing; a library that cannot be mapped wants memory.
      const std::string& why = osmesa().error;
      if (why.find("No such file") != std::string::npos || why.empty())
        throw std::runtime_error("OSMesa: cannot open libOSMesa.so.8 (install libosmesa6, or use --backend egl)");
      throw std::runtime_error("OSMesa: cannot load libOSMesa.so.8: " + why + addressSpaceNote());
    }
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = osmesa().createContextAttribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("OSMesa: could not create an OpenGL 4.5 core context" + addressSpaceNote());
    // OSMesaMakeCurrent needs a client buffer even though lenslab only draws into FBOs.
    buffer_.resize(4 * kBufferSide * kBufferSide);
    if (!osmesa().makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSide, kBufferSide)) {
      osmesa().destroyContext(context_);
      throw std::runtime_error("OSMesa: could not make the context current");
    }
    try {
      loadGlFunctions(&osmesaProc, "OSMesa");
    } catch (...) {
      osmesa().destroyContext(context_);
      throw;
    }
  }
  ~OsmesaContext() override { osmesa().destroyContext(context_); }
  Backend backend() const override { return Backend::OSMesa; }
  void makeCurrent() override {
    if (!osmesa().makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSide, kBufferSide))
      throw std::runtime_error("OSMesa: could not make the context current");
  }

 private:
  static constexpr int kBufferSide = 4;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace lenslab
