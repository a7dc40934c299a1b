#pragma once
// Shader programs from files in shaders/. The folder comes from CMake (the source tree) and the
// environment variable LENSLAB_SHADER_DIR overrides it. `#include "file.glsl"` lines are expanded
// (relative to the including file, then to the shader folder) with #line directives, so compile
// errors name the real file and line. A compile or link error throws with file, line and the
// driver's info log.
#include "gl/Object.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lenslab::gl {

std::filesystem::path shaderDirectory();

struct ShaderSource {
  std::string text;                     // expanded, ready for glShaderSource
  std::vector<std::string> files;       // index = the source-string number in #line directives
};

// Reads `relativePath` under shaderDirectory() and expands includes. `defines` are inserted after
// the #version line as "#define NAME" (used for shader variants).
ShaderSource loadShaderSource(const std::filesystem::path& relativePath,
                              const std::vector<std::string>& defines = {});

// Rewrites "0(12) : error ..." in a driver log to "scene/scene.frag:12: error ...".
std::string annotateInfoLog(const std::string& log, const std::vector<std::string>& files);

Program buildProgram(const std::filesystem::path& vertexPath,
                     const std::filesystem::path& fragmentPath,
                     const std::vector<std::string>& defines = {});

}  // namespace lenslab::gl
