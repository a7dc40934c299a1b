// The glTF loader over the Khronos sample models and the glTF-Validator's test files in
// ../shared/gltf (skipped where that folder is absent), plus small files written here.
#include "core/Error.h"
#include "scene/GltfLoader.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

fs::path sharedDirectory() {
  if (const char* env = std::getenv("LENSLAB_SHARED_DIR"); env && *env) return env;
  return LENSLAB_SHARED_DIR;
}

#define REQUIRE_SHARED(relative)                                                          \
  const fs::path path = sharedDirectory() / (relative);                                    \
  if (!fs::exists(path)) {                                                                 \
    GTEST_SKIP() << path << " is absent (../shared holds the glTF test data)";             \
  }                                                                                        \
  static_assert(true)

Scene loadSample(const std::string& relative) {
  return loadGltf(sharedDirectory() / "gltf/samples" / relative);
}

bool finiteBounds(const Bounds& b) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(b.min[i]) || !std::isfinite(b.max[i])) return false;
  return true;
}

// ---- the sample models ----

TEST(GltfSamples, EveryVariantLoadsOrIsRefusedWithOneLine) {
  REQUIRE_SHARED("gltf/samples");
  int loaded = 0, refused = 0;
  for (const auto& entry : fs::recursive_directory_iterator(path)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    SCOPED_TRACE(entry.path().string());
    try {
      const Scene scene = loadGltf(entry.path());
      ++loaded;
      if (scene.triangleCount() > 0) {
        EXPECT_TRUE(finiteBounds(scene.bounds));
      }
      for (const Instance& instance : scene.instances) {
        ASSERT_GE(instance.mesh, 0);
        ASSERT_LT(static_cast<std::size_t>(instance.mesh), scene.meshes.size());
      }
      for (const Mesh& mesh : scene.meshes) {
        ASSERT_EQ(mesh.indices.size() % 3, 0u);
        for (std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertices.size());
        for (const Vertex& v : mesh.vertices) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f);
      }
    } catch (const InputError& e) {
      ++refused;
      const std::string message = e.what();
      EXPECT_FALSE(message.empty());
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  EXPECT_GE(loaded, 50) << "most sample variants should load";
  EXPECT_EQ(refused, 1) << "only the Draco box is expected to be refused";
}

TEST(GltfSamples, DracoIsRefusedByName) {
  REQUIRE_SHARED("gltf/samples/Box/glTF-Draco/Box.gltf");
  try {
    loadGltf(path);
    FAIL() << "loaded a Draco-compressed file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("KHR_draco_mesh_compression"), std::string::npos) << e.what();
  }
}

TEST(GltfSamples, KnownFacts) {
  REQUIRE_SHARED("gltf/samples");
  EXPECT_EQ(loadSample("Box/glTF/Box.gltf").triangleCount(), 12u);
  EXPECT_EQ(loadSample("Box/glTF-Binary/Box.glb").triangleCount(), 12u);
  EXPECT_EQ(loadSample("TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf").triangleCount(), 1u);
  EXPECT_EQ(loadSample("MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf").triangleCount(), 16u)
      << "triangles, strip and fan become 16 triangles; points and lines are left out";
  // Two scenes; the default is scene 1 (two triangles), not scene 0 (one).
  const Scene multiple = loadSample("MultipleScenes/glTF/MultipleScenes.gltf");
  EXPECT_EQ(multiple.triangleCount(), 2u);
  EXPECT_FALSE(multiple.notes.empty());
  // Mesh reuse: one mesh, two instances.
  const Scene simple = loadSample("SimpleMeshes/glTF/SimpleMeshes.gltf");
  EXPECT_EQ(simple.meshes.size(), 1u);
  EXPECT_EQ(simple.instances.size(), 2u);
  EXPECT_EQ(loadSample("BoxWithSpaces/glTF/Box With Spaces.gltf").triangleCount(), 12u);
  EXPECT_EQ(loadSample("UnicodeTest/glTF/Unicode\u2764\u267bTest.gltf").triangleCount(), 2u);
}

TEST(GltfSamples, Cameras) {
  REQUIRE_SHARED("gltf/samples/Cameras/glTF/Cameras.gltf");
  const Scene scene = loadGltf(path);
  ASSERT_EQ(scene.cameras.size(), 2u);
  const SceneCamera& p = scene.cameras[0];
  EXPECT_TRUE(p.perspective);
  EXPECT_DOUBLE_EQ(p.yfovRadians, 0.7);
  EXPECT_DOUBLE_EQ(p.aspectRatio, 1.0);
  EXPECT_DOUBLE_EQ(p.znear, 0.01);
  EXPECT_DOUBLE_EQ(p.zfar, 100.0);
  EXPECT_EQ(glm::dvec3(p.worldFromCamera[3]), glm::dvec3(0.5, 0.5, 3.0));
  const SceneCamera& o = scene.cameras[1];
  EXPECT_FALSE(o.perspective);
  EXPECT_DOUBLE_EQ(o.xmag, 1.0);
  EXPECT_DOUBLE_EQ(o.ymag, 1.0);
}

TEST(GltfSamples, SparseSubstitutionIsApplied) {
  REQUIRE_SHARED("gltf/samples/SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf");
  const Scene scene = loadGltf(path);
  ASSERT_EQ(scene.meshes.size(), 1u);
  // The sparse part moves vertices 8, 10 and 12 to (1, 2), (3, 3) and (5, 4).
  for (const glm::vec3 expected : {glm::vec3(1, 2, 0), glm::vec3(3, 3, 0), glm::vec3(5, 4, 0)}) {
    bool found = false;
    for (const Vertex& v : scene.meshes[0].vertices) found |= glm::length(v.position - expected) < 1e-6f;
    EXPECT_TRUE(found) << "no vertex at (" << expected.x << ", " << expected.y << ")";
  }
  EXPECT_DOUBLE_EQ(scene.bounds.max.y, 4.0);
}

TEST(GltfSamples, TexturesMaterialsAndColours) {
  REQUIRE_SHARED("gltf/samples");
  const Scene textured = loadSample("BoxTextured/glTF-Binary/BoxTextured.glb");
  ASSERT_EQ(textured.textures.size(), 1u);
  ASSERT_EQ(textured.images.size(), 1u);
  EXPECT_EQ(textured.images[0].width, 256);
  EXPECT_EQ(textured.images[0].height, 256);
  EXPECT_EQ(textured.images[0].rgba8.size(), 256u * 256u * 4u);
  ASSERT_EQ(textured.materials.size(), 1u);
  EXPECT_EQ(textured.materials[0].baseColorTexture, 0);

  const Scene unlit = loadSample("UnlitTest/glTF/UnlitTest.gltf");
  ASSERT_FALSE(unlit.materials.empty());
  for (const Material& m : unlit.materials) EXPECT_TRUE(m.unlit) << m.name;

  const Scene colours = loadSample("VertexColorTest/glTF/VertexColorTest.gltf");
  bool anyColoured = false;
  for (const Mesh& m : colours.meshes) anyColoured |= m.hasVertexColors;
  EXPECT_TRUE(anyColoured);

  const Scene alpha = loadSample("AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf");
  int masks = 0;
  for (const Material& m : alpha.materials) masks += m.alphaMode == AlphaMode::Mask;
  EXPECT_GE(masks, 3);
}

TEST(GltfSamples, MissingNormalsBecomeFlatUnitNormals) {
  REQUIRE_SHARED("gltf/samples/Triangle/glTF/Triangle.gltf");
  const Scene scene = loadGltf(path);
  ASSERT_EQ(scene.meshes.size(), 1u);
  for (const Vertex& v : scene.meshes[0].vertices) {
    EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f) << "the triangle lies in z = 0, counter-clockwise toward +z";
  }
}

// ---- the validator's test files ----

TEST(GltfValidatorFiles, EachGetsTheVerdictItsReportImplies) {
  REQUIRE_SHARED("gltf/invalid/expected.json");
  std::ifstream in(path);
  const nlohmann::json expected = nlohmann::json::parse(in);
  ASSERT_GE(expected.size(), 50u);
  int refused = 0;
  for (const auto& entry : expected) {
    const std::string file = entry["file"];
    const int errors = entry["numErrors"];
    SCOPED_TRACE(file + " (" + std::to_string(errors) + " errors)");
    const auto start = std::chrono::steady_clock::now();
    try {
      loadGltf(path.parent_path() / file);
      EXPECT_EQ(errors, 0) << "loaded a file the validator finds errors in";
    } catch (const InputError& e) {
      ++refused;
      const std::string message = e.what();
      EXPECT_GT(message.size(), file.size() + 4) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    // Not a timing claim: a generous bound that tells a hang from slowness.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  }
  EXPECT_GE(refused, 47);
}

// ---- files written here ----

class GltfWritten : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lenslab-gltf-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A one-buffer glTF whose buffer holds `floats` then `indices` as a data: URI.
  fs::path write(nlohmann::json gltf, const std::vector<float>& floats, const std::vector<std::uint16_t>& indices = {}) {
    std::string bytes(reinterpret_cast<const char*>(floats.data()), floats.size() * 4);
    bytes.append(reinterpret_cast<const char*>(indices.data()), indices.size() * 2);
    while (bytes.size() % 4) bytes.push_back('\0');
    gltf["asset"] = {{"version", "2.0"}};
    gltf["buffers"] = {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}};
    const fs::path file = dir_ / "scene.gltf";
    std::ofstream(file) << gltf.dump();
    return file;
  }

  static std::string base64(const std::string& in) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
      const std::uint32_t b0 = static_cast<unsigned char>(in[i]);
      const std::uint32_t b1 = i + 1 < in.size() ? static_cast<unsigned char>(in[i + 1]) : 0;
      const std::uint32_t b2 = i + 2 < in.size() ? static_cast<unsigned char>(in[i + 2]) : 0;
      const std::uint32_t n = (b0 << 16) | (b1 << 8) | b2;
      out += table[(n >> 18) & 63];
      out += table[(n >> 12) & 63];
      out += i + 1 < in.size() ? table[(n >> 6) & 63] : '=';
      out += i + 2 < in.size() ? table[n & 63] : '=';
    }
    return out;
  }

  // Four vertices of a unit square in z = 0 and the accessors for them (0: positions).
  static nlohmann::json squareAccessors(std::size_t indexCount) {
    return {{"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                             {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", indexCount * 2}}}},
            {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                            {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                           {{"bufferView", 1}, {"componentType", 5123}, {"count", indexCount}, {"type", "SCALAR"}}}}};
  }
  static std::vector<float> square() { return {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}; }

  static nlohmann::json primitive(int material = -1, int mode = 4) {
    nlohmann::json p = {{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", mode}};
    if (material >= 0) p["material"] = material;
    return p;
  }
  static nlohmann::json mesh(const std::string& name, const nlohmann::json& prim) {
    return {{"name", name}, {"primitives", nlohmann::json::array({prim})}};
  }

  fs::path dir_;
};

TEST_F(GltfWritten, StripsAndFansBecomeCounterClockwiseTriangles) {
  for (int mode : {5, 6}) {
    nlohmann::json g = squareAccessors(4);
    g["meshes"] = nlohmann::json::array({mesh("m", primitive(-1, mode))});
    g["nodes"] = {{{"mesh", 0}}};
    g["scenes"] = {{{"nodes", {0}}}};
    // Strip order 0 1 3 2 and fan order 0 1 2 3 both cover the square with two triangles.
    const std::vector<std::uint16_t> order = mode == 5 ? std::vector<std::uint16_t>{0, 1, 3, 2} : std::vector<std::uint16_t>{0, 1, 2, 3};
    const Scene scene = loadGltf(write(g, square(), order));
    ASSERT_EQ(scene.triangleCount(), 2u) << "mode " << mode;
    for (const Vertex& v : scene.meshes[0].vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f) << "mode " << mode << ": a triangle is wound clockwise";
  }
}

TEST_F(GltfWritten, NodeTransformsComposeMatrixAndTrs) {
  nlohmann::json g = squareAccessors(6);
  g["meshes"] = nlohmann::json::array({mesh("m", primitive())});
  // parent: matrix translating by (10, 0, 0); child: rotate 90° about z, then scale 2, then move (0, 5, 0).
  g["nodes"] = {{{"name", "parent"}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}, {"children", {1}}},
                {{"name", "child"}, {"mesh", 0}, {"translation", {0, 5, 0}}, {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}, {"scale", {2, 2, 2}}}};
  g["scenes"] = {{{"nodes", {0}}}};
  const Scene scene = loadGltf(write(g, square(), {0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(scene.instances.size(), 1u);
  const glm::dvec3 p = glm::dvec3(scene.instances[0].worldFromModel * glm::dvec4(1, 0, 0, 1));
  EXPECT_NEAR(p.x, 10.0, 1e-12);  // (1,0,0) scaled → (2,0,0), rotated → (0,2,0), moved → (0,7,0), parent → (10,7,0)
  EXPECT_NEAR(p.y, 7.0, 1e-12);
  EXPECT_NEAR(scene.bounds.min.x, 8.0, 1e-9);
  EXPECT_NEAR(scene.bounds.max.y, 7.0, 1e-9);
}

TEST_F(GltfWritten, NodeLoopIsRefused) {
  nlohmann::json g = squareAccessors(6);
  g["nodes"] = {{{"name", "a"}, {"children", {1}}}, {{"name", "b"}, {"children", {0}}}};
  g["scenes"] = {{{"nodes", {0}}}};
  try {
    loadGltf(write(g, square(), {0, 1, 2, 0, 2, 3}));
    FAIL() << "loaded a node loop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loop"), std::string::npos) << e.what();
  }
}

TEST_F(GltfWritten, OnlyWhatTheSceneUsesIsKept) {
  nlohmann::json g = squareAccessors(6);
  g["materials"] = {{{"name", "unused"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}},
                    {{"name", "used"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 1, 0, 1}}}}}};
  g["meshes"] = nlohmann::json::array({mesh("drawn", primitive(1)), mesh("not drawn", primitive(0))});
  g["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}}};
  g["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
  g["scene"] = 0;
  const Scene scene = loadGltf(write(g, square(), {0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "used");
  EXPECT_EQ(scene.meshes[0].material, 0);
}

TEST_F(GltfWritten, UnsupportedRequiredExtensionIsNamed) {
  nlohmann::json g = squareAccessors(6);
  g["extensionsUsed"] = {"KHR_materials_unlit", "EXT_meshopt_compression"};
  g["extensionsRequired"] = {"EXT_meshopt_compression"};
  try {
    loadGltf(write(g, square(), {0, 1, 2, 0, 2, 3}));
    FAIL() << "loaded a file requiring an unsupported extension";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("EXT_meshopt_compression"), std::string::npos) << e.what();
  }
}

TEST_F(GltfWritten, IndexOutOfRangeIsRefused) {
  nlohmann::json g = squareAccessors(3);
  g["meshes"] = nlohmann::json::array({mesh("m", primitive())});
  g["nodes"] = {{{"mesh", 0}}};
  g["scenes"] = {{{"nodes", {0}}}};
  EXPECT_THROW(loadGltf(write(g, square(), {0, 1, 9})), InputError);
}

TEST(GltfFiles, MissingFileIsOneLineNamingIt) {
  try {
    loadGltf("/no/such/scene.gltf");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/scene.gltf"), std::string::npos);
  }
}

}  // namespace
}  // namespace lenslab
