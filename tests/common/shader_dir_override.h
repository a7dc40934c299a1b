#pragma once
// Points LENSLAB_SHADER_DIR at another folder for a scope (a test's own shaders), then puts back
// what was there.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace lenslab {

class ShaderDirOverride {
 public:
  explicit ShaderDirOverride(const std::filesystem::path& dir) {
    if (const char* old = std::getenv("LENSLAB_SHADER_DIR")) old_ = old;
    setenv("LENSLAB_SHADER_DIR", dir.c_str(), 1);
  }
  ~ShaderDirOverride() {
    if (old_.empty())
      unsetenv("LENSLAB_SHADER_DIR");
    else
      setenv("LENSLAB_SHADER_DIR", old_.c_str(), 1);
  }
  ShaderDirOverride(const ShaderDirOverride&) = delete;
  ShaderDirOverride& operator=(const ShaderDirOverride&) = delete;

 private:
  std::string old_;
};

}  // namespace lenslab
