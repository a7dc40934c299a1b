#pragma once
// Shader programs from shaders/: read from a folder (LENSLAB_SHADER_DIR, or the source tree for a
// developer's build) or from the copies compiled into the library; core/DataPaths.h says which.
// `#include "file.glsl"` lines are expanded (relative to the including file, then to the shader
// folder) with #line directives, so compile errors name the real file and line. A compile or link
// error throws with file, line and the driver's info log.
#include "gl/Object.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::gl {

struct ShaderSource {
  std::string text;                // expanded, ready for glShaderSource
  std::vector<std::string> files;  // index = the source-string number in #line directives
};

// Reads `relativePath` (e.g. "scene/scene.frag") and expands includes. `defines` are inserted
// after the #version line as "#define NAME" (used for shader variants). The first form reads where
// shaderDirectory() (core/DataPaths.h) says; the second from `folder`, or from the compiled-in
// copies when `folder` is nullopt.
ShaderSource loadShaderSource(const std::filesystem::path& relativePath, const std::vector<std::string>& defines = {});
ShaderSource loadShaderSource(const std::filesystem::path& relativePath, const std::vector<std::string>& defines,
                              const std::optional<std::filesystem::path>& folder);

// Rewrites "0(12) : error ..." in a driver log to "scene/scene.frag:12: error ...".
std::string annotateInfoLog(const std::string& log, const std::vector<std::string>& files);

Program buildProgram(const std::filesystem::path& vertexPath, const std::filesystem::path& fragmentPath,
                     const std::vector<std::string>& defines = {});
// With a geometry shader between the two.
Program buildProgramWithGeometry(const std::filesystem::path& vertexPath, const std::filesystem::path& geometryPath,
                                 const std::filesystem::path& fragmentPath,
                                 const std::vector<std::string>& defines = {});

}  // namespace lenslab::gl
