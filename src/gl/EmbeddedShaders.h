#pragma once
// The GLSL of shaders/, compiled into the library (cmake/EmbedShaders.cmake writes the table at
// build time from the list in CMakeLists.txt), so that an installed lenslab, or a program linking
// the library, needs no shader files. gl/Shader.h reads from here unless a folder is chosen
// (core/DataPaths.h).
#include <span>
#include <string_view>

namespace lenslab::gl {

struct EmbeddedShader {
  std::string_view path;  // relative to shaders/, with '/' separators: "scene/scene.frag"
  std::string_view text;  // the file's bytes
};

std::span<const EmbeddedShader> embeddedShaders();

}  // namespace lenslab::gl
