#pragma once
// Scenes of alphaMode BLEND quads for the tests of both renderers' blending (tests/render/alpha_blend_test.cpp,
// raycast_compare_test.cpp, tests/scene/blend_order_test.cpp): quads facing +z, placed apart in
// depth so that the rasterizer's back-to-front order by bounds centre is the true order.
#include "scene/ProceduralScenes.h"
#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>

namespace lenslab::test {

// Adds a quad of material `material` at `centre` (world), facing +z; returns its instance index.
inline std::size_t addQuad(Scene& scene, const glm::dvec3& centre, double halfWidth, double halfHeight, int material,
                           int gltfNode = -1) {
  scene.meshes.push_back(quadMesh(halfWidth, halfHeight, material));
  Instance instance;
  instance.mesh = static_cast<int>(scene.meshes.size()) - 1;
  instance.worldFromModel = glm::translate(glm::dmat4(1.0), centre);
  instance.gltfNode = gltfNode;
  scene.instances.push_back(instance);
  scene.bounds = computeBounds(scene);
  return scene.instances.size() - 1;
}

// Adds a material of straight-alpha colour `rgba`, alphaMode BLEND (OPAQUE when `blend` is
// false), unlit or lit as a dielectric of roughness 0.5; returns its index.
inline int addMaterial(Scene& scene, const glm::vec4& rgba, bool unlit, bool blend = true) {
  Material m;
  m.name = blend ? "blend" : "opaque";
  m.baseColorFactor = rgba;
  m.unlit = unlit;
  m.metallicFactor = 0.0f;
  m.roughnessFactor = 0.5f;
  m.alphaMode = blend ? AlphaMode::Blend : AlphaMode::Opaque;
  m.doubleSided = true;
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

// Adds an 8 × 8 texture of coloured cells whose alpha runs from 0 to 1 across it (sRGB colour,
// linear alpha, as glTF stores them); returns its Scene::textures index.
inline int addAlphaTexture(Scene& scene) {
  TextureImage image;
  image.name = "alpha cells";
  image.width = image.height = 8;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool odd = (x / 2 + y / 2) % 2 != 0;
      for (const int v : {odd ? 230 : 40, 120, odd ? 40 : 220, (x * 255) / 7})
        image.rgba8.push_back(static_cast<std::uint8_t>(v));
    }
  scene.images.push_back(image);
  Texture texture;
  texture.image = static_cast<int>(scene.images.size()) - 1;
  scene.textures.push_back(texture);
  return static_cast<int>(scene.textures.size()) - 1;
}

}  // namespace lenslab::test
