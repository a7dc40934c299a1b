#pragma once
// A current OpenGL 4.5 core context without a window, with the glad loader initialised.
// OSMesa renders on the CPU anywhere (llvmpipe); EGL uses a GPU through the EGL device platform
// when one is there, and Mesa's surfaceless platform otherwise. Render into framebuffer objects:
// these contexts have no default framebuffer worth drawing to.
#include <memory>
#include <string>

namespace lenslab {

enum class Backend { OSMesa, Egl };

// "osmesa" / "egl".
const char* backendName(Backend backend);

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  virtual Backend backend() const = 0;
  // Makes this context the calling thread's current one: a process holding several (the Python
  // module's renderers) switches between them; a context is created current. Throws
  // std::runtime_error when the driver refuses.
  virtual void makeCurrent() = 0;
  // GL_RENDERER and GL_VERSION as the driver reports them.
  std::string renderer() const;
  std::string version() const;
};

// GL_RENDERER of whichever context is current: a headless one or a window's (the view's).
std::string currentRenderer();
// Waits until the GPU has done all it was given (glFinish): wall time around GPU work is honest.
void finishGpuWork();

// Throws std::runtime_error with the reason (library missing, 4.5 core unavailable, ...).
std::unique_ptr<GlContext> createHeadlessContext(Backend backend);

// Loads GL entry points through `getProcAddress` and checks that 4.5 core and clip control are
// there. Each context kind calls it once its context is current.
using GlProc = void (*)();
void loadGlFunctions(GlProc (*getProcAddress)(const char*), const char* what);

// Implementations.
std::unique_ptr<GlContext> createOsmesaContext();
std::unique_ptr<GlContext> createEglContext();

}  // namespace lenslab
