#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lenslab {

Mesh boxMesh(const glm::dvec3& h, int material) {
  Mesh mesh;
  mesh.name = "box";
  mesh.material = material;
  const glm::vec3 half(h);
  // Each face: its normal n and two in-face axes a, b; the corners go round a, b, −a, −b.
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    const glm::vec3 a = glm::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 b = glm::cross(n, a);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const glm::vec2& c : corners) {
      Vertex v;
      v.position = half * (n + c.x * a + c.y * b);
      v.normal = n;
      v.uv = 0.5f * (c + 1.0f);
      mesh.vertices.push_back(v);
    }
    // Wind each face counter-clockwise as seen from outside (from the +n side).
    const bool ccw = glm::dot(glm::cross(a, b), n) > 0.0f;
    if (ccw)
      mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    else
      mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
  }
  return mesh;
}

Mesh quadMesh(double halfWidth, double halfHeight, int material) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.material = material;
  const float w = static_cast<float>(halfWidth);
  const float hgt = static_cast<float>(halfHeight);
  const glm::vec3 p[4] = {{-w, -hgt, 0}, {w, -hgt, 0}, {w, hgt, 0}, {-w, hgt, 0}};
  const glm::vec2 uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (int i = 0; i < 4; ++i) {
    Vertex v;
    v.position = p[i];
    v.normal = {0, 0, 1};
    v.uv = uv[i];
    mesh.vertices.push_back(v);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

namespace {

int addUnlitMaterial(Scene& scene, const glm::vec3& color, bool doubleSided) {
  Material m;
  m.name = "unlit";
  m.baseColorFactor = glm::vec4(color, 1.0f);
  m.unlit = true;
  m.doubleSided = doubleSided;
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

}  // namespace

Scene markerScene(const std::vector<Marker>& markers) {
  Scene scene;
  scene.source = "marker scene";
  scene.lighting.background = glm::vec3(0.0f);
  for (const Marker& marker : markers) {
    const int material = addUnlitMaterial(scene, marker.color, false);
    scene.meshes.push_back(boxMesh(glm::dvec3(marker.halfSize), material));
    Instance instance;
    instance.mesh = static_cast<int>(scene.meshes.size()) - 1;
    instance.worldFromModel = glm::translate(glm::dmat4(1.0), marker.center);
    scene.instances.push_back(instance);
  }
  scene.bounds = computeBounds(scene);
  return scene;
}

void addUnlitQuad(Scene& scene, const glm::dmat4& worldFromModel, double halfWidth, double halfHeight,
                  const glm::vec3& color) {
  const int material = addUnlitMaterial(scene, color, true);
  scene.meshes.push_back(quadMesh(halfWidth, halfHeight, material));
  Instance instance;
  instance.mesh = static_cast<int>(scene.meshes.size()) - 1;
  instance.worldFromModel = worldFromModel;
  scene.instances.push_back(instance);
  scene.bounds = computeBounds(scene);
}

}  // namespace lenslab
