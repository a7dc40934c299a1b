// Where lenslab finds shaders and bundled scenes (core/DataPaths.h), as seen from the build tree:
// the source tree's folders, the environment first. The installed, moved layout is checked by
// tests/install/install_test.sh on a real installation.
#include "core/DataPaths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// Sets (or, with nullopt, unsets) an environment variable for one scope.
class EnvironmentVariable {
 public:
  EnvironmentVariable(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      setenv(name, value->c_str(), 1);
    else
      unsetenv(name);
  }
  ~EnvironmentVariable() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

const fs::path kSourceAssets = LENSLAB_UNIT_ASSET_DIR;

TEST(DataPaths, ExecutableIsThisTest) {
  EXPECT_EQ(executablePath().filename(), "lenslab_unit_tests");
  EXPECT_TRUE(executablePath().is_absolute());
  EXPECT_TRUE(runningFromBuildTree());
}

TEST(DataPaths, BuildTreeReadsTheSourceTree) {
  const EnvironmentVariable shaderDir("LENSLAB_SHADER_DIR", std::nullopt);
  const EnvironmentVariable assetDir("LENSLAB_ASSET_DIR", "");  // empty counts as unset
  const std::optional<fs::path> shaders = shaderDirectory();
  ASSERT_TRUE(shaders.has_value()) << "a build-tree executable should read shaders/, not the compiled-in copies";
  EXPECT_TRUE(fs::equivalent(*shaders, kSourceAssets.parent_path() / "shaders")) << *shaders;
  EXPECT_TRUE(fs::equivalent(assetDirectory(), kSourceAssets)) << assetDirectory();
}

TEST(DataPaths, EnvironmentOverridesBoth) {
  const EnvironmentVariable shaderDir("LENSLAB_SHADER_DIR", "/somewhere/shaders");
  const EnvironmentVariable assetDir("LENSLAB_ASSET_DIR", "/somewhere/assets");
  EXPECT_EQ(shaderDirectory(), fs::path("/somewhere/shaders"));
  EXPECT_EQ(assetDirectory(), fs::path("/somewhere/assets"));
}

}  // namespace
}  // namespace lenslab
