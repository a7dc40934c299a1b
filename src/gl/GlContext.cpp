#include "gl/GlContext.h"

#include <glad/gl.h>

#include <stdexcept>
#include <string>

namespace lenslab {

const char* backendName(Backend backend) { return backend == Backend::OSMesa ? "osmesa" : "egl"; }

namespace {

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

std::string GlContext::renderer() const { return glString(GL_RENDERER); }
std::string GlContext::version() const { return glString(GL_VERSION); }
std::string currentRenderer() { return glString(GL_RENDERER); }
void finishGpuWork() { glFinish(); }

void loadGlFunctions(GlProc (*getProcAddress)(const char*), const char* what) {
  const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress));
  if (version == 0) throw std::runtime_error(std::string(what) + ": could not load OpenGL functions");
  if (GLAD_VERSION_MAJOR(version) < 4 || (GLAD_VERSION_MAJOR(version) == 4 && GLAD_VERSION_MINOR(version) < 5))
    throw std::runtime_error(std::string(what) + ": OpenGL 4.5 core is needed, the driver gives " +
                             std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                             std::to_string(GLAD_VERSION_MINOR(version)));
}

std::unique_ptr<GlContext> createHeadlessContext(Backend backend) {
  return backend == Backend::OSMesa ? createOsmesaContext() : createEglContext();
}

}  // namespace lenslab
