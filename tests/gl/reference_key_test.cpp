// The sweep's cached ray-cast reference is keyed by everything it depends on: changing any input
// of the shading (a material's emission, metallic-roughness, occlusion, normal map; a light) gives
// another key. (No GL needed; it lives beside the sweep, in the GL tests' executable.)
#include "io/CameraJson.h"
#include "report/Sweep.h"
#include "scene/EnvironmentPrefilter.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <set>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

TEST(ReferenceKey, ChangesWithEveryShadingInput) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  const Camera camera = loadCameraJson(assets / "rows/camera-dof.json").camera;
  const ImageSize size{64, 48};
  const SweepOptions options;
  const std::string base = referenceKey(scene, camera, size, options);
  EXPECT_EQ(referenceKey(scene, camera, size, options), base) << "the key is deterministic";
  PunctualLight light;
  light.worldPosition = glm::dvec3(0.0, 2.0, 0.0);
  const std::pair<const char*, std::function<void(Scene&)>> changes[] = {
      {"emissive", [](Scene& s) { s.materials[0].emissive = glm::vec3(0.5f); }},
      {"emissiveTexture", [](Scene& s) { s.materials[0].emissiveTexture.texture = 0; }},
      {"metallicFactor", [](Scene& s) { s.materials[0].metallicFactor = 0.5f; }},
      {"roughnessFactor", [](Scene& s) { s.materials[0].roughnessFactor = 0.5f; }},
      {"metallicRoughnessTexture", [](Scene& s) { s.materials[0].metallicRoughnessTexture.texture = 0; }},
      {"occlusionTexture", [](Scene& s) { s.materials[0].occlusionTexture.texture = 0; }},
      {"occlusionTexture.texCoord", [](Scene& s) { s.materials[0].occlusionTexture.texCoord = 1; }},
      {"occlusionStrength", [](Scene& s) { s.materials[0].occlusionStrength = 0.5f; }},
      {"normalTexture", [](Scene& s) { s.materials[0].normalTexture.texture = 0; }},
      {"normalTexture uv transform", [](Scene& s) { s.materials[0].normalTexture.uvFromTexCoord[2][0] = 0.5f; }},
      {"normalScale", [](Scene& s) { s.materials[0].normalScale = 0.5f; }},
      {"a light", [&](Scene& s) { s.lights.push_back(light); }},
      {"its intensity", [&](Scene& s) { s.lights.push_back(light); s.lights[0].intensity = 2.0f; }},
      {"its position", [&](Scene& s) { s.lights.push_back(light); s.lights[0].worldPosition.x = 1e-9; }},
      {"its cone", [&](Scene& s) { s.lights.push_back(light); s.lights[0].outerConeAngleRadians = 0.5f; }},
      {"its type", [&](Scene& s) { s.lights.push_back(light); s.lights[0].type = LightType::Spot; }},
  };
  std::set<std::string> keys{base};
  for (const auto& [what, change] : changes) {
    Scene changed = scene;
    change(changed);
    const std::string key = referenceKey(changed, camera, size, options);
    EXPECT_NE(key, base) << what;
    keys.insert(key);
  }
  EXPECT_EQ(keys.size(), std::size(changes) + 1) << "every change its own key";
}

// A small environment, prefiltered quickly: `tint` scales one texel, so that two differ in one pixel.
std::shared_ptr<const PrefilteredEnvironment> smallEnvironment(float tint) {
  EnvironmentImage image{16, 8, std::vector<glm::vec3>(16 * 8, glm::vec3(0.5f, 0.6f, 0.7f))};
  image.at(3, 2) *= tint;
  PrefilterSettings settings;
  settings.diffuseWidth = 8;
  settings.specularWidth = 8;
  settings.specularLevels = 3;
  settings.samplesPerTexel = 16;
  return std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(image, settings));
}

// --environment on sweep: the reference depends on the environment's contents, intensity and
// rotation, so each gives another key; without one the key does not change.
TEST(ReferenceKey, ChangesWithTheEnvironment) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  const Camera camera = loadCameraJson(assets / "rows/camera-dof.json").camera;
  const ImageSize size{64, 48};
  const SweepOptions options;
  const std::string none = referenceKey(scene, camera, size, options);
  Scene copy = scene;
  copy.environment = nullptr;
  EXPECT_EQ(referenceKey(copy, camera, size, options), none) << "no environment: the key stays";

  const auto with = [&](std::shared_ptr<const PrefilteredEnvironment> maps, EnvironmentPlacement placement) {
    Scene s = scene;
    s.environment = std::make_shared<const EnvironmentLookup>(std::move(maps), placement);
    return referenceKey(s, camera, size, options);
  };
  const auto maps = smallEnvironment(1.0f);
  const std::string base = with(maps, {0.0, 1.0f});
  EXPECT_NE(base, none) << "an environment";
  EXPECT_EQ(with(maps, {0.0, 1.0f}), base) << "the same environment, the same key";
  EXPECT_EQ(with(smallEnvironment(1.0f), {0.0, 1.0f}), base) << "the same pixels prefiltered again, the same key";
  const std::string contents = with(smallEnvironment(2.0f), {0.0, 1.0f});
  const std::string intensity = with(maps, {0.0, 2.0f});
  const std::string rotation = with(maps, {90.0, 1.0f});
  EXPECT_NE(contents, base) << "one texel brighter";
  EXPECT_NE(intensity, base) << "--environment-intensity";
  EXPECT_NE(rotation, base) << "--environment-rotation";
  EXPECT_EQ((std::set<std::string>{none, base, contents, intensity, rotation}).size(), 5u) << "every change its own key";
}

}  // namespace
}  // namespace lenslab
