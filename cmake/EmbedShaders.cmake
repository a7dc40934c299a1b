# Writes a C++ file holding the GLSL sources as raw string literals (gl/EmbeddedShaders.h).
# Run as a script at build time:
#   cmake -DSHADER_DIR=<shaders/> -DSHADERS=<a,b,...> -DOUTPUT=<file.cpp> -P cmake/EmbedShaders.cmake
# SHADERS are paths relative to SHADER_DIR, separated by commas (a ;-list does not survive a
# custom command's command line intact).
foreach(var SHADER_DIR SHADERS OUTPUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "EmbedShaders.cmake: -D${var}=... is required")
  endif()
endforeach()

set(delimiter "lenslab_glsl")
string(REPLACE "," ";" shaders "${SHADERS}")
set(entries "")
foreach(shader IN LISTS shaders)
  file(READ "${SHADER_DIR}/${shader}" text)
  string(FIND "${text}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "EmbedShaders.cmake: ${shader} contains )${delimiter}\", which ends the raw string literal")
  endif()
  string(APPEND entries "    {\"${shader}\", R\"${delimiter}(${text})${delimiter}\"},\n")
endforeach()

set(content "// Written by cmake/EmbedShaders.cmake from shaders/ at build time: edit the shaders, not this.
#include \"gl/EmbeddedShaders.h\"

namespace lenslab::gl {
namespace {

constexpr EmbeddedShader kShaders[] = {
${entries}};

}  // namespace

std::span<const EmbeddedShader> embeddedShaders() { return kShaders; }

}  // namespace lenslab::gl
")
file(WRITE "${OUTPUT}" "${content}")
