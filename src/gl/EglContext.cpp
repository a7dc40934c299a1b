// EGL without a window: the EGL device platform (a GPU on a server), else Mesa's surfaceless
// platform (llvmpipe). No config and no surface: lenslab draws into FBOs.
#include "gl/GlContext.h"

#include <glad/gl.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {
namespace {

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  Backend backend() const override { return Backend::Egl; }
  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error("EGL: could not make the context current");
  }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

// Makes a 4.5 core context current on `display`, or returns EGL_NO_CONTEXT (display terminated).
EGLContext makeCurrentContext(EGLDisplay display) {
  if (display == EGL_NO_DISPLAY) return EGL_NO_CONTEXT;
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return EGL_NO_CONTEXT;
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  const EGLint attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) {
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  return context;
}

bool isSoftwareRenderer() {
  auto getString = reinterpret_cast<const GLubyte* (*)(GLenum)>(eglGetProcAddress("glGetString"));
  if (!getString) return true;
  const GLubyte* r = getString(GL_RENDERER);
  const std::string renderer = r ? reinterpret_cast<const char*>(r) : "";
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

template <class F>
F eglProc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

}  // namespace

std::unique_ptr<GlContext> createEglContext() {
  auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  if (!getPlatformDisplay)
    throw std::runtime_error("EGL: eglGetPlatformDisplayEXT is missing (is libEGL from Mesa or glvnd installed?)");

  // Prefer a hardware device; keep the first software one as a fallback.
  if (queryDevices) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (queryDevices(16, devices, &count)) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLContext context = makeCurrentContext(display);
        if (context == EGL_NO_CONTEXT) continue;
        if (!isSoftwareRenderer()) {
          loadGlFunctions(reinterpret_cast<GlProc (*)(const char*)>(&eglGetProcAddress), "EGL");
          return std::make_unique<EglContext>(display, context);
        }
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
      }
    }
  }
  EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLContext context = makeCurrentContext(display);
  if (context == EGL_NO_CONTEXT)
    throw std::runtime_error(
        "EGL: no device or surfaceless display gives an OpenGL 4.5 core context; try --backend osmesa");
  loadGlFunctions(reinterpret_cast<GlProc (*)(const char*)>(&eglGetProcAddress), "EGL");
  return std::make_unique<EglContext>(display, context);
}

}  // namespace lenslab
