// KHR_lights_punctual and metallic-roughness in the loader: lights placed by their nodes in the
// extension's units, material factors read, and every bad value refused in one line that names
// the light (or material) and the field.
#include "../common/animated_gltf.h"
#include "../common/refusal.h"
#include "../common/temp_dir_test.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace lenslab {
namespace {

using test::AnimatedGltf;
using json = nlohmann::json;

class LightsFile : public test::TempDirTest {
 protected:
  // A triangle, and the lights given, each placed by its own node with the JSON `placements[i]`.
  AnimatedGltf withLights(const json& lights, const std::vector<json>& placements) {
    AnimatedGltf g;
    g.node({{"mesh", g.triangle()}});
    g.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
    g.gltf["extensions"]["KHR_lights_punctual"]["lights"] = lights;
    for (std::size_t i = 0; i < placements.size(); ++i) {
      json node = placements[i];
      node["extensions"]["KHR_lights_punctual"]["light"] = node.value("light", static_cast<int>(i));
      node.erase("light");
      g.node(node);
    }
    return g;
  }
  Scene load(const AnimatedGltf& g) { return loadGltf(g.write(dir_ / "lights.gltf")); }
  std::string refusal(const AnimatedGltf& g) {
    return test::refusalOf([&] { (void)load(g); });
  }
};

TEST_F(LightsFile, LightsArePlacedByTheirNodesInTheExtensionsUnits) {
  const json lights = json::array({{{"type", "directional"}, {"intensity", 3.5}, {"color", {1.0, 0.5, 0.25}}},
                                   {{"type", "point"}, {"intensity", 40.0}, {"range", 7.0}, {"name", "bulb"}},
                                   {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.4}}}}});
  const double h = std::sqrt(0.5);
  const Scene scene = load(withLights(lights, {{{"rotation", {-h, 0.0, 0.0, h}}},  // −Z turned to −Y: shining down
                                               {{"translation", {1.0, 2.0, 3.0}}},
                                               {{"translation", {0.0, 5.0, 0.0}}, {"rotation", {-h, 0.0, 0.0, h}}}}));
  ASSERT_EQ(scene.lights.size(), 3u);
  const PunctualLight& sun = scene.lights[0];
  EXPECT_EQ(sun.type, LightType::Directional);
  EXPECT_FLOAT_EQ(sun.intensity, 3.5f);
  EXPECT_EQ(sun.color, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_NEAR(sun.worldDirection.y, -1.0, 1e-12);
  const PunctualLight& bulb = scene.lights[1];
  EXPECT_EQ(bulb.type, LightType::Point);
  EXPECT_EQ(bulb.name, "bulb");
  EXPECT_EQ(bulb.range, 7.0);
  EXPECT_EQ(bulb.worldPosition, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_EQ(bulb.gltfNode, 2);
  const PunctualLight& spot = scene.lights[2];
  EXPECT_EQ(spot.type, LightType::Spot);
  EXPECT_FLOAT_EQ(spot.innerConeAngleRadians, 0.1f);
  EXPECT_FLOAT_EQ(spot.outerConeAngleRadians, 0.4f);
  EXPECT_NEAR(spot.worldDirection.y, -1.0, 1e-12);
  EXPECT_EQ(spot.worldPosition, glm::dvec3(0.0, 5.0, 0.0));
  for (const std::string& note : scene.notes) EXPECT_EQ(note.find("KHR_lights_punctual"), std::string::npos) << note;
}

TEST_F(LightsFile, BadLightsAreRefusedNamingTheLightAndTheField) {
  const std::pair<json, const char*> cases[] = {
      {{{"type", "area"}}, "light 0 type is \"area\"; give directional, point or spot"},
      {{{"type", "point"}, {"intensity", -1.0}},
       "light 0 intensity: -1 is out of range; give a finite value from 0 to 3.4e+38"},
      {{{"type", "point"}, {"intensity", 3.5e38}},
       "light 0 intensity: 3.5e+38 is out of range; give a finite value from 0 to 3.4e+38"},
      {{{"type", "point"}, {"color", {1.0, 2.0, 0.0}}}, "light 0 color[1] is 2; give a number in [0, 1]"},
      {{{"type", "point"}, {"color", {1.0, 0.0}}}, "light 0 color has 2 numbers"},
      {{{"type", "point"}, {"range", -2.0}}, "light 0 range is -2"},
      {{{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}},
       "light 0 spot.outerConeAngle is 2; give an angle in (0, pi/2]"},
      {{{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.4}}}},
       "light 0 spot.innerConeAngle is 0.5"},
  };
  for (const auto& [light, words] : cases) {
    const std::string message = refusal(withLights(json::array({light}), {json::object()}));
    EXPECT_NE(message.find(words), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  const std::string badIndex = refusal(withLights(json::array({{{"type", "point"}}}), {{{"light", 3}}}));
  EXPECT_NE(badIndex.find("KHR_lights_punctual.light is 3; the file has 1 lights"), std::string::npos) << badIndex;
  const std::string noDirection =
      refusal(withLights(json::array({{{"type", "directional"}}}), {{{"scale", {1.0, 1.0, 0.0}}}}));
  EXPECT_NE(noDirection.find("no direction"), std::string::npos) << noDirection;
}

TEST_F(LightsFile, AtMostEightLightsArePlaced) {
  std::vector<json> placements(8, json{{"light", 0}});
  EXPECT_EQ(load(withLights(json::array({{{"type", "point"}}}), placements)).lights.size(), 8u);
  placements.push_back(json{{"light", 0}});
  const std::string message = refusal(withLights(json::array({{{"type", "point"}}}), placements));
  EXPECT_NE(message.find("beyond the 8 lenslab shades"), std::string::npos) << message;
}

TEST_F(LightsFile, MetallicRoughnessFactorsAreReadAndCheckedAndTheDefaultMaterialIsTheSpecifications) {
  AnimatedGltf g;
  g.node({{"mesh", g.triangle()}});
  g.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  g.gltf["materials"] =
      json::array({{{"pbrMetallicRoughness", {{"metallicFactor", 0.25}, {"roughnessFactor", 0.75}}}}});
  const Scene scene = load(g);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_FLOAT_EQ(scene.materials[0].metallicFactor, 0.25f);
  EXPECT_FLOAT_EQ(scene.materials[0].roughnessFactor, 0.75f);
  EXPECT_EQ(Material{}.metallicFactor, 1.0f) << "glTF's default material is a rough metal";
  EXPECT_EQ(Material{}.roughnessFactor, 1.0f);
  g.gltf["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 1.5;
  const std::string message = refusal(g);
  EXPECT_NE(message.find("material 0 pbrMetallicRoughness.metallicFactor is 1.5; give a number in [0, 1]"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace lenslab
