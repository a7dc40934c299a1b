// Shader errors are reported with the file, the line and the driver's log.
#include "gl/EmbeddedShaders.h"
#include "gl/Shader.h"
#include "../common/gl_test_context.h"
#include "../common/shader_dir_override.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

TEST(Shader, CompileErrorNamesTheIncludedFileAndLine) {
  LENSLAB_REQUIRE_GL();
  const fs::path dir = fs::temp_directory_path() / "lenslab-shader-test";
  fs::remove_all(dir);
  write(dir / "bad/ok.vert", "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  write(dir / "common/helper.glsl", "// helper\nfloat helper() {\n  return undefined_name;\n}\n");
  write(dir / "bad/bad.frag",
        "#version 450 core\n#include \"../common/helper.glsl\"\nout vec4 c;\nvoid main() { c = vec4(helper()); }\n");
  const ShaderDirOverride override(dir);
  try {
    gl::buildProgram("bad/ok.vert", "bad/bad.frag");
    FAIL() << "a broken shader compiled";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad/bad.frag"), std::string::npos) << message;
    EXPECT_NE(message.find("common/helper.glsl:3"), std::string::npos) << message;
    EXPECT_NE(message.find("undefined_name"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  fs::remove_all(dir);
}

TEST(Shader, MissingShaderFolderSaysHowToFixIt) {
  LENSLAB_REQUIRE_GL();
  const ShaderDirOverride override("/nonexistent/lenslab/shaders");
  try {
    gl::buildProgram("scene/scene.vert", "scene/scene.frag");
    FAIL() << "built a program from a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("LENSLAB_SHADER_DIR"), std::string::npos) << e.what();
  }
}

TEST(Shader, ExpandsIncludesWithLineDirectives) {
  LENSLAB_REQUIRE_GL();
  const gl::ShaderSource source = gl::loadShaderSource("scene/scene.frag", {"VARIANT_X"});
  // The file itself, then each include in the order met (nested ones where they are included).
  // (locations.glsl twice: environment_textures.glsl includes it for its other includer too,
  // and its include guard empties the second copy.)
  ASSERT_EQ(source.files.size(), 9u);
  EXPECT_EQ(source.files[0], "scene/scene.frag");
  EXPECT_EQ(source.files[1], "common/locations.glsl");
  EXPECT_EQ(source.files[2], "common/material_maps.glsl");
  EXPECT_EQ(source.files[3], "common/environment_textures.glsl");
  EXPECT_EQ(source.files[4], "common/locations.glsl");
  EXPECT_EQ(source.files[5], "common/environment.glsl");
  EXPECT_EQ(source.files[6], "common/dfg_filtered.glsl");
  EXPECT_EQ(source.files[7], "common/brdf.glsl");
  EXPECT_EQ(source.files[8], "common/shade_surface.glsl");
  EXPECT_EQ(source.text.rfind("#version 450 core\n#define VARIANT_X\n", 0), 0u);
  EXPECT_NE(source.text.find("vec3 punctualRadiance("), std::string::npos);
}

// The shaders compiled into the library (what an installed lenslab uses) are the source tree's,
// every one of them: a shader added to shaders/ but not to LENSLAB_SHADERS in CMakeLists.txt
// would work in the build tree and fail once installed.
TEST(EmbeddedShaders, MatchTheSourceTree) {
  const fs::path shaders = fs::path(LENSLAB_TEST_ASSET_DIR).parent_path() / "shaders";
  std::map<std::string, std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(shaders)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    files[fs::relative(entry.path(), shaders).generic_string()] = text.str();
  }
  ASSERT_FALSE(files.empty()) << shaders;
  std::map<std::string, std::string> embedded;
  for (const gl::EmbeddedShader& shader : gl::embeddedShaders())
    embedded[std::string(shader.path)] = std::string(shader.text);
  for (const auto& [path, text] : files) {
    const auto it = embedded.find(path);
    if (it == embedded.end())
      ADD_FAILURE() << "shaders/" << path << " is not compiled in: add it to LENSLAB_SHADERS in CMakeLists.txt";
    else
      EXPECT_EQ(it->second, text) << "shaders/" << path << " differs from its compiled-in copy";
  }
  for (const auto& entry : embedded)
    EXPECT_TRUE(files.count(entry.first)) << "compiled in but not in shaders/: " << entry.first;
}

// Reading from the compiled-in copies expands includes exactly as reading the folder does.
TEST(EmbeddedShaders, ExpandAsTheFolderDoes) {
  const fs::path shaders = fs::path(LENSLAB_TEST_ASSET_DIR).parent_path() / "shaders";
  int withIncludes = 0;
  for (const gl::EmbeddedShader& shader : gl::embeddedShaders()) {
    if (shader.path.ends_with(".glsl")) continue;  // included, never compiled on its own
    const gl::ShaderSource fromFolder = gl::loadShaderSource(shader.path, {"VARIANT_X"}, shaders);
    const gl::ShaderSource compiledIn = gl::loadShaderSource(shader.path, {"VARIANT_X"}, std::nullopt);
    EXPECT_EQ(compiledIn.text, fromFolder.text) << shader.path;
    EXPECT_EQ(compiledIn.files, fromFolder.files) << shader.path;
    withIncludes += compiledIn.files.size() > 1;
  }
  EXPECT_GE(withIncludes, 2);  // scene.frag and accumulate.frag include common/ code
  try {
    gl::loadShaderSource("scene/missing.frag", {}, std::nullopt);
    FAIL() << "loaded a shader that is not compiled in";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("scene/missing.frag"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lenslab
