// The glTF loader: over the Khronos sample models and the glTF-Validator's test files of the
// external corpus (LENSLAB_GLTF_CORPUS_DIR; the suites GltfSamples, GltfSampleVariant and
// GltfValidatorFile, which ctest runs as the entry `corpus`, not `unit`), and over small files
// written here that each test one rule with a known answer.
#include "../common/gltf_corpus.h"
#include "core/Error.h"
#include "core/Text.h"
#include "scene/GltfLoader.h"
#include "scene/SceneAnimation.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <OpenImageIO/strutil.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace lenslab {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// ---- Scene.cpp ----

TEST(SceneTotals, TrianglesAndBoundsCountEveryInstance) {
  Scene scene;
  Mesh triangle;
  triangle.vertices.resize(3);
  triangle.vertices[1].position = {1, 0, 0};
  triangle.vertices[2].position = {0, 1, 0};
  triangle.indices = {0, 1, 2};
  scene.meshes.push_back(triangle);
  EXPECT_TRUE(computeBounds(scene).empty()) << "no instances, nothing drawn";
  scene.instances.push_back({0, glm::dmat4(1.0)});
  scene.instances.push_back({0, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -5)) *
                                    glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1))});
  EXPECT_EQ(scene.triangleCount(), 2u);
  const Bounds b = computeBounds(scene);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(b.min[i], glm::dvec3(-1, 0, -5)[i], 1e-15) << "the rotated copy reaches x = -1, z = -5";
    EXPECT_NEAR(b.max[i], glm::dvec3(1, 1, 0)[i], 1e-15);
  }
}

// ---- the external glTF corpus (../common/gltf_corpus.h) ----
// A suite that reads it belongs in LENSLAB_CORPUS_SUITES (tests/CMakeLists.txt): those run as the
// ctest entry `corpus`, which ctest shows as not run when the corpus is absent.

using test::invalidDirectory;
using test::samplesDirectory;

Scene loadSample(const std::string& relative) { return loadGltf(samplesDirectory() / relative); }

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// ---- what every loaded scene and every refusal must satisfy ----

bool finite(const Bounds& b) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(b.min[i]) || !std::isfinite(b.max[i])) return false;
  return true;
}

// Every index in range, every normal of unit length, images the size they say.
void expectWellFormed(const Scene& scene) {
  for (const Instance& instance : scene.instances) {
    ASSERT_GE(instance.mesh, 0);
    ASSERT_LT(static_cast<std::size_t>(instance.mesh), scene.meshes.size());
  }
  for (const Mesh& mesh : scene.meshes) {
    EXPECT_FALSE(mesh.indices.empty()) << mesh.name;
    EXPECT_EQ(mesh.indices.size() % 3, 0u) << mesh.name;
    for (const std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertices.size()) << mesh.name;
    for (const Vertex& v : mesh.vertices) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f) << mesh.name;
    EXPECT_GE(mesh.material, -1);
    EXPECT_LT(mesh.material, static_cast<int>(scene.materials.size()));
  }
  for (const Material& m : scene.materials)
    for (const TextureRef* r : {&m.baseColorTexture, &m.emissiveTexture, &m.normalTexture}) {
      EXPECT_LT(r->texture, static_cast<int>(scene.textures.size()));
      EXPECT_TRUE(r->texCoord == 0 || r->texCoord == 1);
    }
  for (const Texture& t : scene.textures) {
    ASSERT_GE(t.image, 0);
    EXPECT_LT(t.image, static_cast<int>(scene.images.size()));
  }
  for (const TextureImage& image : scene.images) {
    EXPECT_GT(image.width, 0);
    EXPECT_GT(image.height, 0);
    EXPECT_EQ(image.rgba8.size(), static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4u);
  }
  if (scene.triangleCount() > 0) {
    EXPECT_TRUE(finite(scene.bounds));
  } else {
    EXPECT_TRUE(scene.bounds.empty());
  }
}

void expectOneLineNamingFile(const InputError& e, const fs::path& file) {
  const std::string message = e.what();
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
  EXPECT_GT(message.size(), file.string().size() + 4) << message;
}

// ---- every sample model variant ----

std::vector<std::string> sampleFiles() {
  std::vector<std::string> files;
  std::error_code ec;
  if (fs::is_directory(samplesDirectory(), ec))
    for (const auto& entry : fs::recursive_directory_iterator(samplesDirectory(), ec)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".gltf" || ext == ".glb") files.push_back(fs::relative(entry.path(), samplesDirectory()).string());
    }
  std::sort(files.begin(), files.end());
  if (files.empty()) files.push_back("");  // one case, which skips
  return files;
}

std::string caseName(const std::string& path) {
  std::string name;
  for (const char c : path) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name.empty() ? std::string("absent") : name;
}

// The one sample that lenslab refuses, and the word its message must contain.
const std::map<std::string, std::string> kRefusedSamples = {{"Box/glTF-Draco/Box.gltf", "KHR_draco_mesh_compression"}};

class GltfSampleVariant : public testing::TestWithParam<std::string> {};

TEST_P(GltfSampleVariant, LoadsWithTrianglesOrIsRefusedWithOneLine) {
  if (GetParam().empty()) GTEST_SKIP() << samplesDirectory() << " is absent (the external glTF corpus)";
  const fs::path file = samplesDirectory() / GetParam();
  const auto refused = kRefusedSamples.find(GetParam());
  try {
    Scene scene = loadGltf(file);
    EXPECT_EQ(refused, kRefusedSamples.end()) << "loaded a file lenslab cannot draw";
    EXPECT_GT(scene.triangleCount(), 0u) << "every sample model has triangles";
    expectWellFormed(scene);
    // An animated sample poses at its start, middle and end (finite bounds, nothing out of reach).
    const double durationSeconds = animationDurationSeconds(scene);
    for (const double seconds : {0.0, 0.5 * durationSeconds, durationSeconds})
      if (!scene.animation.empty()) {
        poseScene(scene, seconds);
        expectWellFormed(scene);
      }
  } catch (const InputError& e) {
    ASSERT_NE(refused, kRefusedSamples.end()) << e.what();
    expectOneLineNamingFile(e, file);
    EXPECT_NE(std::string(e.what()).find(refused->second), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, GltfSampleVariant, testing::ValuesIn(sampleFiles()),
                         [](const testing::TestParamInfo<std::string>& param) { return caseName(param.param); });

// ---- facts about particular samples ----

TEST(GltfSamples, DracoBoxIsRefusedNamingTheExtension) {
  const fs::path file = samplesDirectory() / "Box/glTF-Draco/Box.gltf";
  SKIP_UNLESS_EXISTS(file);
  try {
    loadGltf(file);
    FAIL() << "loaded a Draco-compressed file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              file.string() +
                  ": extensionsRequired lists KHR_draco_mesh_compression, which lenslab "
                  "does not support (supported: KHR_materials_unlit, "
                  "KHR_materials_emissive_strength, KHR_lights_punctual, KHR_texture_transform)");
  }
}

TEST(GltfSamples, BoxHasTwelveTrianglesInEveryContainer) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "Box");
  for (const char* file : {"Box/glTF/Box.gltf", "Box/glTF-Binary/Box.glb", "Box/glTF-Embedded/Box.gltf"}) {
    const Scene scene = loadSample(file);
    EXPECT_EQ(scene.triangleCount(), 12u) << file;
    EXPECT_EQ(scene.materials.size(), 1u) << file;
    EXPECT_NEAR(scene.bounds.size().x, 1.0, 1e-6) << file;
  }
}

TEST(GltfSamples, TriangleWithoutIndicesHasOneTriangle) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "TriangleWithoutIndices");
  const Scene scene = loadSample("TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf");
  EXPECT_EQ(scene.triangleCount(), 1u);
  EXPECT_EQ(scene.meshes[0].material, -1) << "no material: glTF's default material";
}

TEST(GltfSamples, CamerasArePerspectiveAndOrthographicWithTheirValues) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "Cameras");
  const Scene scene = loadSample("Cameras/glTF/Cameras.gltf");
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
  EXPECT_DOUBLE_EQ(o.znear, 0.01);
  EXPECT_DOUBLE_EQ(o.zfar, 100.0);
  EXPECT_EQ(glm::dvec3(o.worldFromCamera[3]), glm::dvec3(0.5, 0.5, 3.0));
}

TEST(GltfSamples, MultipleScenesDrawsItsDefaultSceneOne) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "MultipleScenes");
  const Scene scene = loadSample("MultipleScenes/glTF/MultipleScenes.gltf");
  // Scene 0 holds a triangle (mesh 0), scene 1 a square of two triangles (mesh 1).
  EXPECT_EQ(scene.triangleCount(), 2u);
  ASSERT_EQ(scene.meshes.size(), 1u);
  bool noted = false;
  for (const std::string& note : scene.notes) noted |= note.find("scene 1") != std::string::npos;
  EXPECT_TRUE(noted);
}

// Reads `count` elements of `size` bytes from a bufferView of the sample's .bin, independently
// of the loader.
std::vector<unsigned char> viewData(const json& gltf, const std::string& bin, int view, std::size_t byteOffset,
                                    std::size_t bytes) {
  const json& v = gltf["bufferViews"][static_cast<std::size_t>(view)];
  const std::size_t at = v.value("byteOffset", std::size_t{0}) + byteOffset;
  return {bin.begin() + static_cast<std::ptrdiff_t>(at), bin.begin() + static_cast<std::ptrdiff_t>(at + bytes)};
}

TEST(GltfSamples, SparseAccessorValuesAreSubstituted) {
  const fs::path file = samplesDirectory() / "SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf";
  SKIP_UNLESS_EXISTS(file);
  const json gltf = json::parse(readText(file));
  const std::string bin = readText(file.parent_path() / gltf["buffers"][0]["uri"].get<std::string>());
  const json& positions = gltf["accessors"][1];
  const json& sparse = positions["sparse"];
  ASSERT_EQ(sparse["indices"]["componentType"], 5123);
  const auto count = sparse["count"].get<std::size_t>();
  const auto targetBytes = viewData(gltf, bin, sparse["indices"]["bufferView"].get<int>(),
                                    sparse["indices"].value("byteOffset", 0u), count * 2);
  const auto valueBytes = viewData(gltf, bin, sparse["values"]["bufferView"].get<int>(),
                                   sparse["values"].value("byteOffset", 0u), count * 12);
  const auto indexBytes = viewData(gltf, bin, gltf["accessors"][0]["bufferView"].get<int>(), 0, 36 * 2);

  const Scene scene = loadGltf(file);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  // Without normals the triangles are unwelded: loaded vertex j is file vertex indices[j].
  ASSERT_EQ(mesh.vertices.size(), 36u);
  int checked = 0;
  for (std::size_t s = 0; s < count; ++s) {
    std::uint16_t target;
    std::memcpy(&target, &targetBytes[s * 2], 2);
    glm::vec3 value;
    std::memcpy(glm::value_ptr(value), &valueBytes[s * 12], 12);
    glm::vec3 base;
    std::memcpy(glm::value_ptr(base), &bin[gltf["bufferViews"][1].value("byteOffset", 0u) + target * 12u], 12);
    EXPECT_NE(value, base) << "the sparse value should differ from the base value it replaces";
    for (std::size_t j = 0; j < 36; ++j) {
      std::uint16_t original;
      std::memcpy(&original, &indexBytes[j * 2], 2);
      if (original != target) continue;
      EXPECT_EQ(mesh.vertices[j].position, value) << "file vertex " << target;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  EXPECT_DOUBLE_EQ(scene.bounds.max.y, 4.0) << "the substituted vertices raise the top to y = 4";
}

TEST(GltfSamples, BoxTexturedDecodesItsOneImage) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "BoxTextured");
  for (const char* file : {"BoxTextured/glTF/BoxTextured.gltf", "BoxTextured/glTF-Binary/BoxTextured.glb",
                           "BoxTextured/glTF-Embedded/BoxTextured.gltf"}) {
    const Scene scene = loadSample(file);
    ASSERT_EQ(scene.textures.size(), 1u) << file;
    ASSERT_EQ(scene.images.size(), 1u) << file;
    EXPECT_EQ(scene.images[0].width, 256) << file;
    EXPECT_EQ(scene.images[0].height, 256) << file;
    EXPECT_EQ(scene.images[0].rgba8.size(), 256u * 256u * 4u) << file;
    EXPECT_EQ(scene.images[0].rgba8[3], 255) << "an opaque PNG gets alpha 255";
    ASSERT_EQ(scene.materials.size(), 1u) << file;
    EXPECT_EQ(scene.materials[0].baseColorTexture.texture, 0) << file;
  }
}

TEST(GltfSamples, UnlitTestMaterialsAreUnlit) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "UnlitTest");
  for (const char* file : {"UnlitTest/glTF/UnlitTest.gltf", "UnlitTest/glTF-Binary/UnlitTest.glb"}) {
    const Scene scene = loadSample(file);
    ASSERT_FALSE(scene.materials.empty());
    for (const Material& m : scene.materials) EXPECT_TRUE(m.unlit) << file << " " << m.name;
  }
}

TEST(GltfSamples, VertexColorTestHasAColouredMesh) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "VertexColorTest");
  const Scene scene = loadSample("VertexColorTest/glTF/VertexColorTest.gltf");
  int coloured = 0, plain = 0;
  for (const Mesh& m : scene.meshes) {
    if (!m.hasVertexColors) {
      ++plain;
      continue;
    }
    ++coloured;
    bool anyNotWhite = false;
    for (const Vertex& v : m.vertices) {
      anyNotWhite |= v.color != glm::vec4(1.0f);
      for (int c = 0; c < 4; ++c) ASSERT_TRUE(v.color[c] >= 0.0f && v.color[c] <= 1.0f);
    }
    EXPECT_TRUE(anyNotWhite) << m.name;
  }
  EXPECT_EQ(coloured, 1);
  EXPECT_EQ(plain, 1) << "the label mesh has no COLOR_0";
}

TEST(GltfSamples, MissingNormalsBecomeFlatUnitNormals) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "Triangle");
  const Scene scene = loadSample("Triangle/glTF/Triangle.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  EXPECT_EQ(mesh.vertices.size(), mesh.indices.size()) << "flat normals unweld: three vertices per triangle";
  for (const Vertex& v : mesh.vertices)
    EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f) << "the triangle lies in z = 0, counter-clockwise seen from +z";
}

TEST(GltfSamples, FileNamesWithSpacesAndUnicodeLoad) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "BoxWithSpaces");
  SKIP_UNLESS_EXISTS(samplesDirectory() / "UnicodeTest");
  const Scene spaces = loadSample("BoxWithSpaces/glTF/Box With Spaces.gltf");
  EXPECT_EQ(spaces.triangleCount(), 12u);
  ASSERT_EQ(spaces.images.size(), 3u)
      << "the base colour, metallic-roughness and normal images' %20-encoded URIs resolve";
  for (const char* file :
       {"UnicodeTest/glTF/Unicode\u2764\u267bTest.gltf", "UnicodeTest/glTF-Binary/Unicode\u2764\u267bTest.glb"}) {
    const Scene unicode = loadSample(file);
    EXPECT_EQ(unicode.triangleCount(), 2u) << file;
    EXPECT_EQ(unicode.images.size(), 1u) << file;
  }
}

TEST(GltfSamples, PrimitiveModesKeepTrianglesStripsAndFans) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "MeshPrimitiveModes");
  const Scene scene = loadSample("MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf");
  EXPECT_EQ(scene.triangleCount(), 16u) << "triangles, strip and fan; points, lines and loops are left out";
  bool noted = false;
  for (const std::string& note : scene.notes) noted |= note.find("points and lines") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(GltfSamples, ReusedMeshIsOneMeshWithTwoInstances) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "SimpleMeshes");
  const Scene scene = loadSample("SimpleMeshes/glTF/SimpleMeshes.gltf");
  EXPECT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_NE(scene.instances[0].worldFromModel, scene.instances[1].worldFromModel);
}

TEST(GltfSamples, MaterialsKeepAlphaModesSamplersAndSides) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "AlphaBlendModeTest");
  SKIP_UNLESS_EXISTS(samplesDirectory() / "TextureSettingsTest");
  const Scene alpha = loadSample("AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf");
  std::vector<float> cutoffs;
  int blends = 0;
  for (const Material& m : alpha.materials) {
    if (m.alphaMode == AlphaMode::Mask) cutoffs.push_back(m.alphaCutoff);
    blends += m.alphaMode == AlphaMode::Blend;
  }
  EXPECT_NE(std::find(cutoffs.begin(), cutoffs.end(), 0.25f), cutoffs.end());
  EXPECT_NE(std::find(cutoffs.begin(), cutoffs.end(), 0.75f), cutoffs.end());
  EXPECT_NE(std::find(cutoffs.begin(), cutoffs.end(), 0.5f), cutoffs.end()) << "the default cutoff";
  EXPECT_GE(blends, 1);

  const Scene settings = loadSample("TextureSettingsTest/glTF/TextureSettingsTest.gltf");
  std::vector<Wrap> wraps;
  for (const Texture& t : settings.textures) wraps.insert(wraps.end(), {t.sampler.wrapS, t.sampler.wrapT});
  for (const Wrap w : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
    EXPECT_NE(std::find(wraps.begin(), wraps.end(), w), wraps.end()) << static_cast<int>(w);
  int doubleSided = 0;
  for (const Material& m : settings.materials) doubleSided += m.doubleSided;
  EXPECT_GT(doubleSided, 0);
  EXPECT_LT(doubleSided, static_cast<int>(settings.materials.size()));
}

TEST(GltfSamples, AFullPbrMaterialDecodesEveryMap) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "DamagedHelmet");
  const Scene scene = loadSample("DamagedHelmet/glTF-Binary/DamagedHelmet.glb");  // five images in the file
  EXPECT_EQ(scene.textures.size(), 5u);  // base colour, metallic-roughness, emissive, occlusion, normal
  EXPECT_EQ(scene.images.size(), 5u);
  ASSERT_EQ(scene.materials.size(), 1u);
  const Material& m = scene.materials[0];
  EXPECT_TRUE(m.emissiveTexture.present());
  EXPECT_EQ(m.emissive, glm::vec3(1.0f));
  EXPECT_TRUE(m.metallicRoughnessTexture.present());
  EXPECT_TRUE(m.occlusionTexture.present());
  EXPECT_NE(m.metallicRoughnessTexture.texture, m.occlusionTexture.texture);
  EXPECT_TRUE(m.normalTexture.present());
  bool noted = false;
  for (const std::string& note : scene.notes) noted |= note.find("left out") != std::string::npos;
  EXPECT_FALSE(noted) << "every map is read";
}

TEST(GltfSamples, IgnoredFeaturesAreNoted) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "SimpleSkin");
  const std::pair<const char*, const char*> cases[] = {{"SimpleSkin/glTF/SimpleSkin.gltf", "skins are ignored"},
                                                       {"AnimatedTriangle/glTF/AnimatedTriangle.gltf", "animation"},
                                                       {"SimpleMorph/glTF/SimpleMorph.gltf", "morph targets"},
                                                       {"ToyCar/glTF/ToyCar.gltf", "KHR_materials_clearcoat"}};
  for (const auto& [file, words] : cases) {
    const Scene scene = loadSample(file);
    bool noted = false;
    for (const std::string& note : scene.notes) noted |= note.find(words) != std::string::npos;
    EXPECT_TRUE(noted) << file << " should note " << words;
  }
}

// ---- the glTF-Validator's test files ----

struct ValidatorCase {
  std::string file;  // relative to gltf/invalid; empty when the data is absent
  int errors = 0;
};

void PrintTo(const ValidatorCase& c, std::ostream* out) { *out << c.file << " (" << c.errors << " errors)"; }

std::vector<ValidatorCase> validatorCases() {
  std::vector<ValidatorCase> cases;
  const fs::path expected = invalidDirectory() / "expected.json";
  if (fs::exists(expected)) {
    const json entries = json::parse(readText(expected), nullptr, false);
    if (entries.is_array())
      for (const json& entry : entries) cases.push_back({entry.value("file", ""), entry.value("numErrors", 0)});
  }
  if (cases.empty()) cases.push_back({});
  return cases;
}

// Every file with errors is refused: none needs an exception, so there is no allow-list. Files
// without errors (warnings only) may load or be refused; lenslab refuses some of them because
// tinygltf 2.7 cannot read them (a buffer without uri in a .gltf, an unknown accessor type) or
// because lenslab reads no URLs (non_relative_uri).
class GltfValidatorFile : public testing::TestWithParam<ValidatorCase> {};

TEST_P(GltfValidatorFile, ErrorsAreRefusedWithOneLineAndNothingCrashesOrHangs) {
  if (GetParam().file.empty())
    GTEST_SKIP() << invalidDirectory() / "expected.json"
                 << " is absent (the external glTF corpus)";
  const fs::path file = invalidDirectory() / GetParam().file;
  const auto start = std::chrono::steady_clock::now();
  try {
    const Scene scene = loadGltf(file);
    EXPECT_EQ(GetParam().errors, 0) << "loaded a file in which the validator finds errors";
    expectWellFormed(scene);
  } catch (const InputError& e) {
    expectOneLineNamingFile(e, file);
  }
  // Not a timing claim: a generous bound that tells a hang from slowness.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

INSTANTIATE_TEST_SUITE_P(Validator, GltfValidatorFile, testing::ValuesIn(validatorCases()),
                         [](const testing::TestParamInfo<ValidatorCase>& param) { return caseName(param.param.file); });

// ---- files written here ----

// data: URIs in the files written here: OpenImageIO's encoder (a library, not a hand-made table).
std::string base64(const std::string& in) { return OIIO::Strutil::base64_encode(in); }

// Small PNGs (made with Python's zlib): 1x1 red, 2x1 green (both RGBA8), 2x1 16-bit grey
// (0x8000, 0xFFFF).
const char* kRedPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGP4z8DwHwAFAAH/iZk9HQAAAABJRU5ErkJggg==";
const char* kGreenPng = "iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAADElEQVR4nGNg+A+BAA/5A/3YOXFBAAAAAElFTkSuQmCC";
const char* kGrey16Png =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAABEAAAAACB2fwVAAAADUlEQVR4nGNoYPj/HwAFAgJ/Fl7EZQAAAABJRU5ErkJggg==";

constexpr int kFloat = 5126, kUByte = 5121, kUShort = 5123, kUInt = 5125;

// Builds a glTF with one buffer: add views and accessors, then write it as .gltf (buffer in a
// data: URI) or .glb (buffer in the BIN chunk).
class GltfBuilder {
 public:
  json gltf = {{"asset", {{"version", "2.0"}}}};

  int view(const void* data, std::size_t bytes, std::size_t stride = 0) {
    while (bin_.size() % 4) bin_.push_back('\0');
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}};
    if (stride) v["byteStride"] = stride;
    bin_.append(static_cast<const char*>(data), bytes);
    return push("bufferViews", v);
  }

  template <class T>
  int accessor(const std::vector<T>& values, int componentType, const char* type, std::size_t count,
               bool normalized = false) {
    json a = {{"bufferView", view(values.data(), values.size() * sizeof(T))},
              {"componentType", componentType},
              {"count", count},
              {"type", type}};
    if (normalized) a["normalized"] = true;
    return push("accessors", a);
  }

  // POSITION accessors need min and max.
  int positions(const std::vector<glm::vec3>& p) {
    std::vector<float> flat;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& v : p) {
      flat.insert(flat.end(), {v.x, v.y, v.z});
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    const int a = accessor(flat, kFloat, "VEC3", p.size());
    gltf["accessors"][static_cast<std::size_t>(a)]["min"] = {lo.x, lo.y, lo.z};
    gltf["accessors"][static_cast<std::size_t>(a)]["max"] = {hi.x, hi.y, hi.z};
    return a;
  }

  int indices(const std::vector<std::uint16_t>& i) { return accessor(i, kUShort, "SCALAR", i.size()); }

  // A mesh of one primitive, drawn by a new root node of scene 0; returns the node.
  int drawnMesh(json primitive, const std::string& name = "m") {
    const int mesh = push("meshes", {{"name", name}, {"primitives", json::array({primitive})}});
    const int node = push("nodes", {{"mesh", mesh}});
    if (!gltf.contains("scenes")) gltf["scenes"] = json::array({{{"nodes", json::array()}}});
    gltf["scenes"][0]["nodes"].push_back(node);
    return node;
  }

  int push(const char* collection, const json& item) {
    gltf[collection].push_back(item);
    return static_cast<int>(gltf[collection].size()) - 1;
  }

  fs::path writeGltf(const fs::path& file) {
    json g = gltf;
    if (!bin_.empty())
      g["buffers"] = {{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin_)}}};
    std::ofstream(file, std::ios::binary) << g.dump();
    return file;
  }

  // The buffer in a file `binName` beside the .gltf, its URI `uri` (as written in the JSON).
  fs::path writeGltfWithExternalBuffer(const fs::path& file, const std::string& binName, const std::string& uri) {
    json g = gltf;
    g["buffers"] = {{{"byteLength", bin_.size()}, {"uri", uri}}};
    std::ofstream(file.parent_path() / binName, std::ios::binary) << bin_;
    std::ofstream(file, std::ios::binary) << g.dump();
    return file;
  }

  // A GLB with the JSON, the BIN chunk, then `extra` chunks of other types.
  std::string glb(const std::vector<std::pair<std::uint32_t, std::string>>& extra = {}) const {
    json g = gltf;
    std::string bin = bin_;
    while (bin.size() % 4) bin.push_back('\0');
    if (!bin.empty()) g["buffers"] = {{{"byteLength", bin_.size()}}};
    std::string text = g.dump();
    while (text.size() % 4) text.push_back(' ');
    std::vector<std::pair<std::uint32_t, std::string>> chunks = {{0x4E4F534Au, text}};
    if (!bin.empty()) chunks.emplace_back(0x004E4942u, bin);
    chunks.insert(chunks.end(), extra.begin(), extra.end());
    std::string body;
    for (const auto& [type, data] : chunks) body += u32(data.size()) + u32(type) + data;
    return "glTF" + u32(2) + u32(12 + body.size()) + body;
  }

 private:
  static std::string u32(std::size_t v) {
    std::string out;
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
    return out;
  }

  std::string bin_;
};

class GltfWritten : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lenslab-gltf-" + std::to_string(::getpid()) + "-" +
                                        testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Scene load(GltfBuilder& b) { return loadGltf(b.writeGltf(dir_ / "scene.gltf")); }

  // The message of the InputError that loading throws ("" and a failure when it loads).
  std::string refusal(GltfBuilder& b) {
    const fs::path file = b.writeGltf(dir_ / "scene.gltf");
    try {
      loadGltf(file);
    } catch (const InputError& e) {
      expectOneLineNamingFile(e, file);
      return e.what();
    }
    ADD_FAILURE() << "loaded " << b.gltf.dump();
    return "";
  }

  fs::path writeBytes(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }

  static GltfBuilder square(std::vector<std::uint16_t> order = {0, 1, 2, 0, 2, 3}) {
    GltfBuilder b;
    const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    b.drawnMesh({{"attributes", {{"POSITION", p}}}, {"indices", b.indices(order)}});
    return b;
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool noted(const Scene& scene, const std::string& part) {
  for (const std::string& note : scene.notes)
    if (contains(note, part)) return true;
  return false;
}

// -- files and containers

TEST(GltfFiles, MissingFileIsOneLineNamingItAndTheReason) {
  try {
    loadGltf("/no/such/x.gltf");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/no/such/x.gltf: cannot read the glTF file (does it exist?)");
  }
}

TEST_F(GltfWritten, DirectoryIsRefused) {
  try {
    loadGltf(dir_);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "is a folder; give the glTF file as a file")) << e.what();
  }
}

TEST_F(GltfWritten, GlbIsRecognisedByMagicAndUnknownChunksAreIgnored) {
  GltfBuilder b = square();
  const Scene plain = loadGltf(writeBytes("plain.glb", b.glb()));
  EXPECT_EQ(plain.triangleCount(), 2u);
  const Scene extra = loadGltf(writeBytes("extra.glb", b.glb({{0x12345678u, std::string(8, 'x')}})));
  EXPECT_EQ(extra.triangleCount(), 2u);
  const Scene renamed = loadGltf(writeBytes("binary.gltf", b.glb()));  // the magic decides, not the name
  EXPECT_EQ(renamed.triangleCount(), 2u);
  EXPECT_THROW(loadGltf(writeBytes("text.glb", square().gltf.dump())), InputError);
}

// In a URI path only %XX is an escape: "a+b.bin" names a file with a plus sign (tinygltf 2.7
// alone would look for "a b.bin"); "%2B" is a plus too, and "%20" a space.
TEST_F(GltfWritten, PlusInABufferUriIsAPlus) {
  GltfBuilder b = square();
  EXPECT_EQ(loadGltf(b.writeGltfWithExternalBuffer(dir_ / "plus.gltf", "a+b.bin", "a+b.bin")).triangleCount(), 2u);
  EXPECT_EQ(loadGltf(b.writeGltfWithExternalBuffer(dir_ / "escaped.gltf", "c+d.bin", "c%2Bd.bin")).triangleCount(), 2u);
  EXPECT_EQ(loadGltf(b.writeGltfWithExternalBuffer(dir_ / "space.gltf", "e f.bin", "e%20f.bin")).triangleCount(), 2u);
  fs::remove(dir_ / "a+b.bin");
  std::ofstream(dir_ / "a b.bin", std::ios::binary) << "not this one";
  EXPECT_THROW(loadGltf(dir_ / "plus.gltf"), InputError);  // looks for a+b.bin, which is gone
}

// A buffer file whose length is not its byteLength: in lenslab's words, naming both lengths (tinygltf
// says "File size mismatch : … requestedBytes …").
TEST_F(GltfWritten, ABufferFileOfAnotherLengthNamesBoth) {
  GltfBuilder b = square();
  const fs::path file = b.writeGltfWithExternalBuffer(dir_ / "short.gltf", "short.bin", "short.bin");
  const std::uintmax_t bytes = fs::file_size(dir_ / "short.bin");
  fs::resize_file(dir_ / "short.bin", bytes - 4);
  std::string m;
  try {
    loadGltf(file);
  } catch (const InputError& e) {
    m = e.what();
  }
  EXPECT_TRUE(contains(m, cat("short.bin holds ", bytes - 4, " bytes, but its buffer's byteLength says ", bytes,
                              "; give the file's own length as byteLength")))
      << m;
}

// Positions are refused beyond ±kMaxWorldCoordinate (after the node transforms), in one line
// naming the mesh; a vertex at 1e38 drew part of its triangle in the raster and nothing in Embree.
TEST_F(GltfWritten, PositionsBeyondTheBoundAreRefused) {
  for (const double x : {1e16, 1e38}) {
    GltfBuilder b;
    const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {static_cast<float>(x), 1, 0}});
    b.drawnMesh({{"attributes", {{"POSITION", p}}}});
    const std::string m = refusal(b);
    EXPECT_TRUE(contains(m, "mesh 0") && contains(m, "beyond +-1e+15")) << m;
  }
  // A node translation carries an in-range mesh out of range too.
  GltfBuilder b = square();
  b.gltf["nodes"][0]["translation"] = {0.0, 2e15, 0.0};
  EXPECT_TRUE(contains(refusal(b), "in world space")) << b.gltf.dump();
  // At the bound it loads.
  GltfBuilder edge;
  const int p = edge.positions({{0, 0, 0}, {1, 0, 0}, {1e15f, 1, 0}});
  edge.drawnMesh({{"attributes", {{"POSITION", p}}}});
  EXPECT_EQ(load(edge).triangleCount(), 1u);
}

TEST_F(GltfWritten, TruncatedGlbIsRefused) {
  const std::string glb = square().glb();
  for (const std::size_t keep :
       {std::size_t{0}, std::size_t{11}, std::size_t{12}, std::size_t{19}, glb.size() / 2, glb.size() - 4}) {
    SCOPED_TRACE(keep);
    EXPECT_THROW(loadGltf(writeBytes("cut.glb", glb.substr(0, keep))), InputError);
  }
}

TEST_F(GltfWritten, DeeplyNestedJsonIsRefusedNotACrash) {
  const std::string deep =
      R"({"asset":{"version":"2.0"},"extras":)" + std::string(100000, '[') + std::string(100000, ']') + "}";
  try {
    loadGltf(writeBytes("deep.gltf", deep));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "nests deeper")) << e.what();
  }
}

// -- extensions

TEST_F(GltfWritten, RequiredUnsupportedExtensionIsRefusedByName) {
  GltfBuilder b = square();
  b.gltf["extensionsUsed"] = {"KHR_materials_unlit", "EXT_meshopt_compression"};
  b.gltf["extensionsRequired"] = {"KHR_materials_unlit", "EXT_meshopt_compression"};
  const fs::path file = dir_ / "scene.gltf";
  EXPECT_EQ(refusal(b), file.string() +
                            ": extensionsRequired lists EXT_meshopt_compression, which lenslab does not support "
                            "(supported: KHR_materials_unlit, KHR_materials_emissive_strength, KHR_lights_punctual, "
                            "KHR_texture_transform)");
  b.gltf["extensionsRequired"] = {"KHR_materials_unlit"};
  const Scene scene = load(b);
  EXPECT_TRUE(noted(scene, "EXT_meshopt_compression")) << "used but not required: a note";
}

// -- nodes

TEST_F(GltfWritten, NodeLoopsAndSharedChildrenAreRefused) {
  {
    GltfBuilder b = square();  // node 0 draws the square; nodes 1 and 2 form a loop nobody draws
    b.push("nodes", {{"children", {2}}});
    b.push("nodes", {{"children", {1}}});
    EXPECT_TRUE(contains(refusal(b), "loop"));
  }
  {
    GltfBuilder b = square();
    b.gltf["nodes"][0]["children"] = {0};
    EXPECT_TRUE(contains(refusal(b), "loop"));
  }
  {
    GltfBuilder b = square();  // node 0 is a child of nodes 1 and 2
    b.push("nodes", {{"children", {0}}});
    b.push("nodes", {{"children", {0}}});
    b.gltf["scenes"][0]["nodes"] = {1, 2};
    EXPECT_TRUE(contains(refusal(b), "at most one parent"));
  }
  {
    GltfBuilder b = square();
    b.gltf["nodes"][0]["children"] = {7};
    EXPECT_TRUE(contains(refusal(b), "node 7, which does not exist"));
  }
}

// glTF: a node's matrix must decompose to translation, rotation and scale; its rotation must be a
// unit quaternion. A float's rounding passes; a projection, a skew and a scaling quaternion do not.
TEST_F(GltfWritten, TransformsTheSpecificationForbidsAreRefusedByName) {
  const auto withNode = [&](const char* key, const nlohmann::json& value) {
    GltfBuilder b = square();
    b.gltf["nodes"][0][key] = value;
    return refusal(b);
  };
  EXPECT_TRUE(contains(withNode("matrix", {1, 0, 0, 0.3, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
                       "node 0: matrix has the bottom row (0.3, 0, 0, 1), not (0, 0, 0, 1)"));
  EXPECT_TRUE(contains(withNode("matrix", {1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
                       "node 0: matrix skews (its columns 1 and 2 are not perpendicular"));
  EXPECT_TRUE(contains(withNode("rotation", {0, 0, 0, 2}),
                       "node 0: rotation (0, 0, 0, 2) has length 2; glTF requires a unit quaternion"));
  EXPECT_TRUE(contains(withNode("rotation", {0, 0, 0, 0}), "has length 0"));
  // What exporters write: floats of a unit quaternion and of a scaled, turned, moved matrix; a
  // zero scale (an object shrunk away) and a mirror are TRS too.
  for (const auto& [key, value] : std::vector<std::pair<const char*, nlohmann::json>>{
           {"rotation", {0.0, 0.70710677, 0.0, 0.70710677}},
           {"matrix", {0, 0, -2, 0, 0, 3, 0, 0, 0.5, 0, 0, 0, 10, 20, 30, 1}},
           {"scale", {0, 1, 1}},
           {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}}) {
    GltfBuilder b = square();
    b.gltf["nodes"][0][key] = value;
    EXPECT_NO_THROW(load(b)) << key << " " << value.dump();
  }
}

TEST_F(GltfWritten, TrsAndMatrixGiveTheSameTransform) {
  const glm::dvec3 t(1, -2, 3), s(2, 3, 0.5);
  const glm::dquat q = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3)));
  const glm::dmat4 expected = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), s);
  GltfBuilder b = square();
  b.gltf["nodes"][0]["translation"] = {t.x, t.y, t.z};
  b.gltf["nodes"][0]["rotation"] = {q.x, q.y, q.z, q.w};
  b.gltf["nodes"][0]["scale"] = {s.x, s.y, s.z};
  const int asMatrix = b.push(
      "nodes", {{"mesh", 0}, {"matrix", std::vector<double>(glm::value_ptr(expected), glm::value_ptr(expected) + 16)}});
  b.gltf["scenes"][0]["nodes"].push_back(asMatrix);
  const Scene scene = load(b);
  ASSERT_EQ(scene.instances.size(), 2u);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(scene.instances[0].worldFromModel[c][r], expected[c][r], 1e-12)
          << "TRS, column " << c << " row " << r;
      EXPECT_NEAR(scene.instances[1].worldFromModel[c][r], expected[c][r], 1e-12)
          << "matrix, column " << c << " row " << r;
    }
}

TEST_F(GltfWritten, HierarchyComposesParentThenChild) {
  GltfBuilder b = square();
  // child (node 0): rotate 90 degrees about z, scale 2, move (0, 5, 0); parent: matrix moving (10, 0, 0).
  b.gltf["nodes"][0]["translation"] = {0, 5, 0};
  b.gltf["nodes"][0]["rotation"] = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  b.gltf["nodes"][0]["scale"] = {2, 2, 2};
  b.push("nodes", {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}, {"children", {0}}});
  b.gltf["scenes"][0]["nodes"] = {1};
  const Scene scene = load(b);
  ASSERT_EQ(scene.instances.size(), 1u);
  // (1, 0, 0) → scaled (2, 0, 0) → rotated (0, 2, 0) → moved (0, 7, 0) → parent (10, 7, 0).
  const glm::dvec3 p(scene.instances[0].worldFromModel * glm::dvec4(1, 0, 0, 1));
  EXPECT_NEAR(p.x, 10.0, 1e-12);
  EXPECT_NEAR(p.y, 7.0, 1e-12);
  EXPECT_NEAR(scene.bounds.min.x, 8.0, 1e-9);
  EXPECT_NEAR(scene.bounds.max.x, 10.0, 1e-9);
  EXPECT_NEAR(scene.bounds.max.y, 7.0, 1e-9);
}

TEST_F(GltfWritten, WithoutScenesEveryRootNodeIsDrawn) {
  GltfBuilder b = square();
  b.gltf.erase("scenes");
  b.push("nodes", {{"mesh", 0}, {"translation", {5, 0, 0}}});
  const Scene scene = load(b);
  EXPECT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.meshes.size(), 1u);
}

// -- primitives

// The triangles of a mesh loaded without normals, as the numbers of the file's vertices (found
// by position: the positions written are distinct).
std::vector<std::array<int, 3>> trianglesAsFileVertices(const Mesh& mesh, const std::vector<glm::vec3>& file) {
  std::vector<std::array<int, 3>> out;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = mesh.vertices[mesh.indices[t + static_cast<std::size_t>(k)]].position;
      tri[static_cast<std::size_t>(k)] = static_cast<int>(std::find(file.begin(), file.end(), p) - file.begin());
    }
    out.push_back(tri);
  }
  return out;
}

TEST_F(GltfWritten, StripsAndFansBecomeListsInTheSpecOrder) {
  // Both outlines are laid out so that every triangle the spec defines is counter-clockwise from +z.
  const std::vector<glm::vec3> strip = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
  const std::vector<glm::vec3> fan = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0, 0}};
  struct Case {
    int mode;
    const std::vector<glm::vec3>* positions;
    std::vector<std::array<int, 3>> expected;
  };
  const Case cases[] = {{5, &strip, {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}}}, {6, &fan, {{1, 2, 0}, {2, 3, 0}, {3, 4, 0}}}};
  for (const Case& c : cases)
    for (const int indexType : {0, kUByte, kUShort, kUInt}) {
      SCOPED_TRACE(cat("mode ", c.mode, ", index componentType ", indexType));
      GltfBuilder b;
      json primitive = {{"attributes", {{"POSITION", b.positions(*c.positions)}}}, {"mode", c.mode}};
      if (indexType == kUByte)
        primitive["indices"] = b.accessor(std::vector<std::uint8_t>{0, 1, 2, 3, 4}, kUByte, "SCALAR", 5);
      if (indexType == kUShort) primitive["indices"] = b.indices({0, 1, 2, 3, 4});
      if (indexType == kUInt)
        primitive["indices"] = b.accessor(std::vector<std::uint32_t>{0, 1, 2, 3, 4}, kUInt, "SCALAR", 5);
      b.drawnMesh(primitive);
      const Scene scene = load(b);
      ASSERT_EQ(scene.meshes.size(), 1u);
      EXPECT_EQ(trianglesAsFileVertices(scene.meshes[0], *c.positions), c.expected);
      for (const Vertex& v : scene.meshes[0].vertices)
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f) << "a triangle is wound clockwise";
    }
}

TEST_F(GltfWritten, PointsLinesAndPrimitivesWithoutPositionAreLeftOutWithANote) {
  GltfBuilder b;
  const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.drawnMesh({{"attributes", {{"POSITION", p}}}, {"mode", 0}});
  b.drawnMesh({{"attributes", {{"POSITION", p}}}, {"mode", 1}});
  b.drawnMesh(
      {{"attributes", json::object({{"TEXCOORD_0", b.accessor(std::vector<float>(6, 0.0f), kFloat, "VEC2", 3)}})}});
  const Scene scene = load(b);
  EXPECT_EQ(scene.triangleCount(), 0u);
  EXPECT_TRUE(scene.bounds.empty()) << "a scene without triangles loads, with empty bounds";
  EXPECT_TRUE(noted(scene, "points and lines"));
  EXPECT_TRUE(noted(scene, "no POSITION"));
}

TEST_F(GltfWritten, MeshNamesCountPrimitivesAndMissingMaterialIsTheDefault) {
  GltfBuilder b;
  const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const json prim = {{"attributes", {{"POSITION", p}}}};
  const int mesh = b.push("meshes", {{"name", "pair"}, {"primitives", {prim, prim}}});
  b.push("nodes", {{"mesh", mesh}});
  b.push("scenes", {{"nodes", {0}}});
  const Scene scene = load(b);
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].name, "pair#0");
  EXPECT_EQ(scene.meshes[1].name, "pair#1");
  EXPECT_EQ(scene.meshes[0].material, -1);
  EXPECT_EQ(scene.instances.size(), 2u) << "one instance per (node, primitive)";
}

TEST_F(GltfWritten, IndexBeyondTheVerticesIsRefused) {
  GltfBuilder b = square({0, 1, 9});
  EXPECT_TRUE(contains(refusal(b), "not below the vertex count 4"));
}

TEST_F(GltfWritten, AccessorBeyondItsBufferViewIsRefused) {
  GltfBuilder b = square();
  b.gltf["accessors"][0]["count"] = 5;  // 5 vertices of 12 bytes in a 48-byte view
  const std::string message = refusal(b);
  EXPECT_TRUE(contains(message, "accessor 0: byteOffset + count*stride exceeds bufferView 0")) << message;
  EXPECT_TRUE(contains(message, "length 48")) << message;
}

TEST_F(GltfWritten, InterleavedAttributesAreReadThroughTheirStride) {
  // position (3 floats) and colour (4 normalised bytes) per vertex: a 16-byte stride.
  struct Packed {
    float position[3];
    std::uint8_t color[4];
  };
  const std::vector<Packed> data = {
      {{0, 0, 0}, {255, 0, 0, 255}}, {{1, 0, 0}, {0, 255, 0, 255}}, {{0, 1, 0}, {0, 0, 255, 51}}};
  GltfBuilder b;
  const int v = b.view(data.data(), data.size() * sizeof(Packed), sizeof(Packed));
  const int p = b.push("accessors", {{"bufferView", v},
                                     {"componentType", kFloat},
                                     {"count", 3},
                                     {"type", "VEC3"},
                                     {"min", {0, 0, 0}},
                                     {"max", {1, 1, 0}}});
  const int c = b.push("accessors", {{"bufferView", v},
                                     {"byteOffset", 12},
                                     {"componentType", kUByte},
                                     {"normalized", true},
                                     {"count", 3},
                                     {"type", "VEC4"}});
  b.drawnMesh({{"attributes", {{"POSITION", p}, {"COLOR_0", c}}}});
  const Scene scene = load(b);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  EXPECT_TRUE(mesh.hasVertexColors);
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[1].position, glm::vec3(1, 0, 0));
  EXPECT_EQ(mesh.vertices[0].color, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(mesh.vertices[2].color, glm::vec4(0, 0, 1, 0.2f));
}

TEST_F(GltfWritten, AttributesMustHaveAGltfFormat) {
  {
    GltfBuilder b = square();  // COLOR_0 of bytes that are not normalised
    b.gltf["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        b.accessor(std::vector<std::uint8_t>(12, 255), kUByte, "VEC3", 4);
    const std::string message = refusal(b);
    EXPECT_TRUE(contains(
        message, "COLOR_0 (accessor 2) is VEC3 of UNSIGNED_BYTE; it must be VEC3/VEC4 of FLOAT or of normalized"))
        << message;
  }
  {
    GltfBuilder b = square();  // normalised 16-bit texture coordinates are fine
    b.gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
        b.accessor(std::vector<std::uint16_t>{0, 0, 65535, 0, 65535, 65535, 0, 65535}, kUShort, "VEC2", 4, true);
    const Scene scene = load(b);
    EXPECT_EQ(scene.meshes[0].vertices[scene.meshes[0].indices[2]].uv, glm::vec2(1, 1));
  }
  {
    GltfBuilder b = square();  // NORMAL with a count other than POSITION's
    b.gltf["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
        b.accessor(std::vector<float>(9, 0.0f), kFloat, "VEC3", 3);
    EXPECT_TRUE(contains(refusal(b), "all must have the same count"));
  }
}

TEST_F(GltfWritten, SparseAccessorsAreSubstitutedAndChecked) {
  // Three vertices, all zero but for the sparse substitution of vertices 1 and 2.
  auto build = [](std::vector<std::uint16_t> targets) {
    GltfBuilder b;
    const std::vector<float> values = {1, 0, 0, 0, 1, 0};
    const int p =
        b.push("accessors", {{"componentType", kFloat},
                             {"count", 3},
                             {"type", "VEC3"},
                             {"sparse",
                              {{"count", 2},
                               {"indices", {{"bufferView", b.view(targets.data(), 4)}, {"componentType", kUShort}}},
                               {"values", {{"bufferView", b.view(values.data(), 24)}}}}}});
    b.drawnMesh({{"attributes", {{"POSITION", p}}}});
    return b;
  };
  GltfBuilder good = build({1, 2});
  const Scene scene = load(good);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].vertices[1].position, glm::vec3(1, 0, 0));
  EXPECT_EQ(scene.meshes[0].vertices[2].position, glm::vec3(0, 1, 0));
  GltfBuilder beyond = build({1, 3});
  EXPECT_TRUE(contains(refusal(beyond), "sparse index 3 is not below the accessor's count (3)"));
  GltfBuilder unordered = build({2, 1});
  EXPECT_TRUE(contains(refusal(unordered), "strictly increase"));
}

TEST_F(GltfWritten, DeclaredMinMaxMustHoldTheData) {
  GltfBuilder b = square();
  b.gltf["accessors"][0]["max"] = {1, 0.5, 0};
  EXPECT_TRUE(contains(refusal(b), "above the declared max 0.5"));
}

// -- materials, textures, images

TEST_F(GltfWritten, OnlyUsedMaterialsTexturesAndImagesAreKeptAndReindexed) {
  GltfBuilder b = square();
  const json tex = {{"index", 0}};
  b.gltf["images"] = {{{"uri", std::string("data:image/png;base64,") + kRedPng}},
                      {{"uri", std::string("data:image/png;base64,") + kGreenPng}}};
  b.gltf["samplers"] = {{{"wrapS", 33071}, {"magFilter", 9728}}};
  b.gltf["textures"] = {{{"source", 0}}, {{"source", 1}, {"sampler", 0}}};
  b.gltf["materials"] = {
      {{"name", "unused"}},
      {{"name", "drawn"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1, 1, 1}}, {"baseColorTexture", {{"index", 1}}}}}},
      {{"name", "other scene"}, {"pbrMetallicRoughness", {{"baseColorTexture", tex}}}}};
  b.gltf["meshes"][0]["primitives"][0]["material"] = 1;
  // A second scene, not drawn, uses material 2 (and so texture 0 and image 0).
  b.push("meshes", {{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 2}}}}});
  b.push("nodes", {{"mesh", 1}});
  b.push("scenes", {{"nodes", {1}}});
  b.gltf["scene"] = 0;
  const Scene scene = load(b);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "drawn");
  EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(0.5f, 1, 1, 1));
  EXPECT_EQ(scene.meshes[0].material, 0);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.materials[0].baseColorTexture.texture, 0);
  EXPECT_EQ(scene.textures[0].sampler.wrapS, Wrap::ClampToEdge);
  EXPECT_EQ(scene.textures[0].sampler.wrapT, Wrap::Repeat);
  EXPECT_EQ(scene.textures[0].sampler.magFilter, Filter::Nearest);
  EXPECT_EQ(scene.textures[0].sampler.minFilter, Filter::LinearMipmapLinear) << "undefined: Scene.h's default";
  ASSERT_EQ(scene.images.size(), 1u);
  EXPECT_EQ(scene.textures[0].image, 0);
  EXPECT_EQ(scene.images[0].width, 2) << "the green image, not the red one";
  EXPECT_EQ(std::vector<std::uint8_t>(scene.images[0].rgba8.begin(), scene.images[0].rgba8.begin() + 4),
            (std::vector<std::uint8_t>{0, 255, 0, 255}));
}

TEST_F(GltfWritten, SixteenBitGreyImagesBecomeRgba8) {
  GltfBuilder b = square();
  b.gltf["images"] = {{{"uri", std::string("data:image/png;base64,") + kGrey16Png}}};
  b.gltf["textures"] = {{{"source", 0}}};
  b.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  const Scene scene = load(b);
  ASSERT_EQ(scene.images.size(), 1u);
  EXPECT_EQ(scene.images[0].rgba8, (std::vector<std::uint8_t>{128, 128, 128, 255, 255, 255, 255, 255}));
}

TEST_F(GltfWritten, BaseColourFromAUvSetBeyondOneIsLeftOutWithANote) {
  GltfBuilder b = square();
  b.gltf["images"] = {{{"uri", std::string("data:image/png;base64,") + kRedPng}}};
  b.gltf["textures"] = {{{"source", 0}}};
  b.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 2}}}}},
                          {"extensions", {{"KHR_materials_unlit", json::object()}}}}};
  b.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  const Scene scene = load(b);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_TRUE(scene.materials[0].unlit);
  EXPECT_FALSE(scene.materials[0].baseColorTexture.present());
  EXPECT_TRUE(scene.images.empty());
  EXPECT_TRUE(noted(scene, "TEXCOORD_2"));
}

TEST_F(GltfWritten, BrokenImagesAreRefusedNamingThem) {
  {
    GltfBuilder b = square();  // cut off in the middle: found without decoding, used or not
    const std::string png(kRedPng);
    b.gltf["images"] = {{{"name", "cut"}, {"uri", "data:image/png;base64," + png.substr(0, 40)}}};
    EXPECT_TRUE(contains(refusal(b), "image 0 \"cut\": PNG data ends before its IEND chunk"));
  }
  {
    GltfBuilder b = square();  // a used image that is no image at all
    b.gltf["images"] = {{{"name", "text"}, {"uri", "data:image/png;base64," + base64("not an image")}}};
    b.gltf["textures"] = {{{"source", 0}}};
    b.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    b.gltf["meshes"][0]["primitives"][0]["material"] = 0;
    EXPECT_TRUE(contains(refusal(b), "image 0 \"text\": neither PNG nor JPEG"));
  }
}

TEST_F(GltfWritten, MaterialValuesMustBeValid) {
  GltfBuilder b = square();
  b.gltf["materials"] = {{{"name", "m"}, {"alphaMode", "SOMETIMES"}}};
  EXPECT_TRUE(contains(refusal(b), "material 0 \"m\": alphaMode \"SOMETIMES\" must be OPAQUE, MASK or BLEND"));
  b.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 2, 1, 1}}}}}};
  EXPECT_TRUE(contains(refusal(b), "baseColorFactor[1] is 2"));
}

TEST_F(GltfWritten, EmissionIsTheFactorTimesTheEmissiveStrength) {
  GltfBuilder b = square();
  b.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  b.gltf["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  b.gltf["extensionsRequired"] = {"KHR_materials_emissive_strength"};
  b.gltf["materials"] = {{{"emissiveFactor", {1.0, 0.5, 0.25}},
                          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 8.0}}}}}}};
  const Scene scene = load(b);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].emissive, glm::vec3(8.0f, 4.0f, 2.0f));
  EXPECT_TRUE(scene.materials[0].emits());
  b.gltf["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -1.0;
  EXPECT_TRUE(contains(refusal(b), "emissiveStrength: -1 is out of range")) << refusal(b);
  // Past a float's largest radiance: refused naming the limit, not rendered as inf.
  b.gltf["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e300;
  EXPECT_TRUE(contains(refusal(b), "give a finite value from 0 to 3.4e+38")) << refusal(b);
  // The factor is glTF's [0, 1] per channel (−1 would emit negative light).
  b.gltf["materials"] = {{{"emissiveFactor", {1.0, -1.0, 0.0}}}};
  EXPECT_TRUE(contains(refusal(b), "emissiveFactor[1] is -1; each must be within [0, 1]")) << refusal(b);
  b.gltf["materials"] = {{{"emissiveFactor", {0.0, 0.0, 0.0}}}};
  EXPECT_FALSE(load(b).materials[0].emits()) << "no emission: nothing added";
}

// -- cameras

TEST_F(GltfWritten, CamerasTakeTheirNodesPlaceAndDefaults) {
  GltfBuilder b = square();
  b.gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  b.gltf["nodes"][0]["camera"] = 0;
  b.gltf["nodes"][0]["translation"] = {1, 2, 3};
  const Scene scene = load(b);
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_EQ(scene.cameras[0].aspectRatio, 0.0) << "absent";
  EXPECT_EQ(scene.cameras[0].zfar, std::numeric_limits<double>::infinity()) << "absent";
  EXPECT_EQ(glm::dvec3(scene.cameras[0].worldFromCamera[3]), glm::dvec3(1, 2, 3));
}

TEST_F(GltfWritten, BadCameraValuesAreRefusedNamingCameraAndField) {
  const std::pair<json, std::string> cases[] = {
      {{{"name", "eye"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.0}, {"znear", 0.1}}}},
       "camera 0 \"eye\": yfov is 0"},
      {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", -1.0}}}}, "camera 0: znear is -1"},
      {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 1.0}, {"zfar", 0.5}}}},
       "zfar 0.5 must be greater than znear 1"},
      {{{"type", "orthographic"}, {"orthographic", {{"xmag", -1.0}, {"ymag", 1.0}, {"znear", 0.0}, {"zfar", 10.0}}}},
       "camera 0: xmag is -1"},
      // glTF: aspectRatio and zfar, when present, are > 0 (tinygltf reads 0 as absent).
      {{{"name", "wide"},
        {"type", "perspective"},
        {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 0.0}}}},
       "camera 0 \"wide\": aspectRatio is 0.0; when present it must be a positive finite number"},
      {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 0.0}}}},
       "camera 0: zfar is 0.0"},
  };
  for (const auto& [camera, expected] : cases) {
    GltfBuilder b = square();
    b.gltf["cameras"] = {camera};
    b.gltf["nodes"][0]["camera"] = 0;
    const std::string message = refusal(b);
    EXPECT_TRUE(contains(message, expected)) << message;
  }
}

TEST_F(GltfWritten, ACameraNodeScaledToZeroIsRefusedNamingTheNode) {
  GltfBuilder b = square();
  b.gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  b.gltf["nodes"][0]["camera"] = 0;
  b.gltf["nodes"][0]["name"] = "Cam";
  b.gltf["nodes"][0]["scale"] = {1, 1, 0};
  const std::string message = refusal(b);
  EXPECT_TRUE(contains(message, "node 0 \"Cam\" (camera 0): its world transform is singular")) << message;
}

// -- robustness

// Fixed-seed mutations of a small textured GLB (bytes flipped, or the file cut short): each must
// load or be refused with an InputError, never crash (run under ASan/UBSan to mean it).
TEST_F(GltfWritten, MutatedFilesLoadOrAreRefusedNeverCrash) {
  GltfBuilder b = square();
  b.gltf["images"] = {{{"uri", std::string("data:image/png;base64,") + kGreenPng}}};
  b.gltf["textures"] = {{{"source", 0}}};
  b.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  b.gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
      b.accessor(std::vector<float>(8, 0.5f), kFloat, "VEC2", 4);
  const std::string original = b.glb();
  std::mt19937 random(20240601);
  int loaded = 0, refused = 0;
  for (int i = 0; i < 400; ++i) {
    std::string bytes = original;
    if (i % 4 == 3) {
      bytes.resize(std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random));
    } else {
      for (int flips = 1 + i % 3; flips > 0; --flips)
        bytes[std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random)] =
            static_cast<char>(std::uniform_int_distribution<int>(0, 255)(random));
    }
    try {
      const Scene scene = loadGltf(writeBytes("mutated.glb", bytes));
      expectWellFormed(scene);
      ++loaded;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
      ++refused;
    }
  }
  EXPECT_EQ(loaded + refused, 400);
}

// -- normal maps, tangents, TEXCOORD_1 and KHR_texture_transform

class GltfMaps : public GltfWritten {
 protected:
  // The square with TEXCOORD_0 (and more attributes from `extra`), drawn with material 0.
  static GltfBuilder texturedSquare(json extra = json::object()) {
    GltfBuilder b;
    const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    json attributes = {{"POSITION", p},
                       {"TEXCOORD_0", b.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}, kFloat, "VEC2", 4)}};
    for (auto& [name, value] : extra.items()) attributes[name] = value;
    b.drawnMesh({{"attributes", attributes}, {"indices", b.indices({0, 1, 2, 0, 2, 3})}, {"material", 0}});
    b.gltf["images"] = {{{"uri", std::string("data:image/png;base64,") + kRedPng}}};
    b.gltf["textures"] = {{{"source", 0}}};
    return b;
  }
};

TEST_F(GltfMaps, TangentsAndTheSecondUvSetAreRead) {
  GltfBuilder b;
  const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  const std::vector<float> tangents{1, 0, 0, 1, 0, 1, 0, -1, 0.6f, 0.8f, 0, 1};
  const std::vector<float> uv1{0.25f, 0.5f, 0.75f, 0.5f, 0.25f, 1.0f};
  b.drawnMesh({{"attributes",
                {{"POSITION", p},
                 {"TANGENT", b.accessor(tangents, kFloat, "VEC4", 3)},
                 {"TEXCOORD_1", b.accessor(uv1, kFloat, "VEC2", 3)}}}});
  const Scene scene = load(b);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  EXPECT_TRUE(mesh.hasTangents);
  ASSERT_EQ(mesh.vertices.size(), 3u);  // flat normals keep one vertex per corner here
  EXPECT_EQ(mesh.vertices[1].tangent, glm::vec4(0, 1, 0, -1));
  EXPECT_NEAR(mesh.vertices[2].tangent.x, 0.6f, 1e-6f);
  EXPECT_EQ(mesh.vertices[2].uv1, glm::vec2(0.25f, 1.0f));
}

TEST_F(GltfMaps, TangentsThatAreNotUnitOrHaveNoSignAreRefusedInOneLine) {
  const std::pair<std::vector<float>, const char*> cases[] = {
      {{1, 0, 0, 0.5f, 1, 0, 0, 1, 1, 0, 0, 1}, "TANGENT: element 0 has w = 0.5; it must be 1 or -1"},
      {{1, 0, 0, 1, 2, 0, 0, 1, 1, 0, 0, 1}, "TANGENT: element 1 has xyz of length 2; it must be a unit vector"}};
  for (const auto& [values, message] : cases) {
    GltfBuilder b;
    const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    b.drawnMesh({{"attributes", {{"POSITION", p}, {"TANGENT", b.accessor(values, kFloat, "VEC4", 3)}}}});
    EXPECT_TRUE(contains(refusal(b), message)) << message;
  }
  GltfBuilder b;
  const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  b.drawnMesh(
      {{"attributes", {{"POSITION", p}, {"TANGENT", b.accessor(std::vector<float>(9, 0.0f), kFloat, "VEC3", 3)}}}});
  EXPECT_TRUE(contains(refusal(b), "TANGENT (accessor 1) is VEC3 of FLOAT; it must be VEC4 FLOAT"));
}

TEST_F(GltfMaps, ANormalMapWithoutTangentsGetsGeneratedOnesAndItsScale) {
  GltfBuilder b = texturedSquare();
  b.gltf["materials"] = {{{"normalTexture", {{"index", 0}, {"scale", 0.5}}}}};
  const Scene scene = load(b);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_TRUE(scene.materials[0].normalTexture.present());
  EXPECT_EQ(scene.materials[0].normalScale, 0.5f);
  const Mesh& mesh = scene.meshes[0];
  EXPECT_TRUE(mesh.hasTangents);
  for (const Vertex& v : mesh.vertices) {
    // The image upright on the square (v falls along +y): ∂P/∂u = +x, bitangent +y, w = +1.
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
  // The same square without a normal map gets no tangents (no tangent path).
  GltfBuilder plain = texturedSquare();
  plain.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  const Scene unmapped = load(plain);
  EXPECT_FALSE(unmapped.meshes[0].hasTangents);
  EXPECT_EQ(unmapped.meshes[0].vertices[0].tangent, glm::vec4(0.0f));
}

TEST_F(GltfMaps, TextureTransformAndTexCoordAreReadOnEveryTextureReference) {
  GltfBuilder b = texturedSquare({{"TEXCOORD_1", json()}});
  b.gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] =
      b.accessor(std::vector<float>(8, 0.5f), kFloat, "VEC2", 4);
  const json transform = {
      {"offset", {0.5, -0.25}}, {"rotation", 1.5707963267948966}, {"scale", {2.0, 3.0}}, {"texCoord", 1}};
  b.gltf["extensionsUsed"] = {"KHR_texture_transform"};
  b.gltf["extensionsRequired"] = {"KHR_texture_transform"};
  json material;
  material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0},
                                                          {"extensions", {{"KHR_texture_transform", transform}}}};
  material["emissiveFactor"] = {1, 1, 1};
  material["emissiveTexture"] = {{"index", 0}, {"texCoord", 1}};
  material["normalTexture"] = {{"index", 0}};
  material["normalTexture"]["extensions"]["KHR_texture_transform"]["offset"] = {0.125, 0};
  b.gltf["materials"] = json::array({material});
  const Scene scene = load(b);
  const Material& m = scene.materials[0];
  EXPECT_EQ(m.baseColorTexture.texCoord, 1) << "the extension's texCoord overrides the textureInfo's";
  // The extension's formula: u' = cos·2u + sin·3v + 0.5, v' = −sin·2u + cos·3v − 0.25 at 90°, the
  // offset within the repeat's period (−0.25 and 0.75 show the same texel).
  const glm::vec3 mapped = m.baseColorTexture.uvFromTexCoord * glm::vec3(0.1f, 0.2f, 1.0f);
  EXPECT_NEAR(mapped.x, 3.0f * 0.2f + 0.5f, 1e-6f);
  EXPECT_NEAR(mapped.y, -2.0f * 0.1f + 0.75f, 1e-6f);
  EXPECT_EQ(m.emissiveTexture.texCoord, 1);
  EXPECT_EQ(m.emissiveTexture.uvFromTexCoord, glm::mat3(1.0f));
  EXPECT_EQ(m.normalTexture.texCoord, 0);
  EXPECT_NEAR((m.normalTexture.uvFromTexCoord * glm::vec3(0.0f, 0.0f, 1.0f)).x, 0.125f, 1e-7f);
  EXPECT_FALSE(noted(scene, "KHR_texture_transform"));
}

TEST_F(GltfMaps, ATextureTransformsRotationOfAnySizeIsReducedToOneTurn) {
  // 1e300 radians is a float's infinity (whose cosine is NaN) unless it is reduced in double first.
  for (const double turns : {1e300, -1e20, 1e6 * 2.0 * std::numbers::pi + 0.5}) {
    GltfBuilder b = texturedSquare();
    json material;
    material["pbrMetallicRoughness"]["baseColorTexture"] = {
        {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", turns}}}}}};
    b.gltf["materials"] = json::array({material});
    const glm::mat3 m = load(b).materials[0].baseColorTexture.uvFromTexCoord;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_TRUE(std::isfinite(m[c][r])) << turns;
    EXPECT_NEAR(m[0][0], std::cos(std::remainder(turns, 2.0 * std::numbers::pi)), 1e-6) << turns;
  }
}

TEST_F(GltfMaps, ATextureTransformsOffsetKeepsItsFractionWithinTheWrapsPeriod) {
  // 10^7 + 0.3 as a float is 10^7: the fraction, the part that shows, would be lost. Brought within
  // the period in double first (1 for repeat, 2 for mirrored repeat; a clamped texture keeps it).
  const std::pair<int, double> cases[] = {{10497, 0.3}, {33648, 0.3}, {33071, 1e7 + 0.3}};
  for (const auto& [wrap, expected] : cases) {
    GltfBuilder b = texturedSquare();
    b.gltf["samplers"] = json::array({{{"wrapS", wrap}, {"wrapT", wrap}}});
    b.gltf["textures"][0]["sampler"] = 0;
    json material;
    material["pbrMetallicRoughness"]["baseColorTexture"] = {
        {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {1e7 + 0.3, -3.0}}}}}}};
    b.gltf["materials"] = json::array({material});
    const glm::mat3 m = load(b).materials[0].baseColorTexture.uvFromTexCoord;
    EXPECT_NEAR(m[2][0], expected, 1e-6 * std::max(1.0, expected)) << "wrap " << wrap;
    EXPECT_NEAR(m[2][1], wrap == 33071 ? -3.0 : wrap == 33648 ? 1.0 : 0.0, 1e-6) << "wrap " << wrap;
  }
}

TEST_F(GltfMaps, MalformedTextureTransformsAreRefusedNamingTheField) {
  const std::pair<json, const char*> cases[] = {
      {{{"offset", {1, 2, 3}}},
       "material 0 baseColorTexture KHR_texture_transform.offset must be an array of 2 numbers"},
      {{{"rotation", "left"}}, "material 0 baseColorTexture KHR_texture_transform.rotation must be a number (radians)"},
      {{{"scale", {1, "x"}}}, "KHR_texture_transform.scale must be an array of 2 numbers"},
      // Past a float's reach: the range named.
      {{{"scale", {1e31, 1}}},
       "KHR_texture_transform.scale: 1e+31 is out of range; give a finite value from -1e+30 to 1e+30"},
      {{{"offset", {0, -1e35}}}, "KHR_texture_transform.offset: -1e+35 is out of range"},
      {{{"texCoord", -1}}, "KHR_texture_transform.texCoord must be an integer >= 0"}};
  for (const auto& [transform, message] : cases) {
    GltfBuilder b = texturedSquare();
    json material;
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0},
                                                            {"extensions", {{"KHR_texture_transform", transform}}}};
    b.gltf["materials"] = json::array({material});
    EXPECT_TRUE(contains(refusal(b), message)) << message;
  }
}

TEST(GltfSamples, NormalMapsTexCoord1AndTextureTransformsOfTheSamples) {
  SKIP_UNLESS_EXISTS(samplesDirectory() / "NormalTangentTest");
  // No TANGENT in the file: generated for every normal-mapped mesh, unit and ⟂ the normal.
  const Scene normalTangent = loadSample("NormalTangentTest/glTF-Binary/NormalTangentTest.glb");
  int mapped = 0;
  for (const Mesh& mesh : normalTangent.meshes) {
    if (mesh.material < 0 || !normalTangent.materials[static_cast<std::size_t>(mesh.material)].normalTexture.present())
      continue;
    ++mapped;
    ASSERT_TRUE(mesh.hasTangents) << mesh.name;
    for (const Vertex& v : mesh.vertices) {
      ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f) << mesh.name;
      ASSERT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-4f) << mesh.name;
    }
  }
  EXPECT_GT(mapped, 0);
  // MultiUVTest: the emissive texture samples TEXCOORD_1.
  const Scene multiUv = loadSample("MultiUVTest/glTF/MultiUVTest.gltf");
  bool secondSet = false;
  for (const Material& m : multiUv.materials)
    secondSet |= m.emissiveTexture.present() && m.emissiveTexture.texCoord == 1;
  EXPECT_TRUE(secondSet);
  // TextureTransformTest: rotation 0.392699 rad on one of its materials.
  const Scene transformed = loadSample("TextureTransformTest/glTF/TextureTransformTest.gltf");
  bool rotated = false;
  for (const Material& m : transformed.materials)
    rotated |= std::abs(m.baseColorTexture.uvFromTexCoord[0][0] - std::cos(0.392699f)) < 1e-5f &&
               std::abs(m.baseColorTexture.uvFromTexCoord[1][0] - std::sin(0.392699f)) < 1e-5f;
  EXPECT_TRUE(rotated);
}

}  // namespace
}  // namespace lenslab
