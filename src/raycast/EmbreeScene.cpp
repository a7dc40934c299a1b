#include "raycast/EmbreeScene.h"

#include "core/MemoryLimit.h"

#include "core/Text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace lenslab {

EmbreeScene::EmbreeScene(const Scene& s) : scene(&s) {
  // LENSLAB_EMBREE_CONFIG is passed to Embree as its device configuration ("isa=sse2",
  // "isa=avx", "verbose=1", ...): it forces another SIMD path for the ray caster, so a test can show
  // that its figures do not hang on the ISA this CPU picks (docs/stability.md).
  const char* config = std::getenv("LENSLAB_EMBREE_CONFIG");
  device = rtcNewDevice(config && *config ? config : nullptr);
  if (!device && config && *config)
    throw InputError(
        cat("LENSLAB_EMBREE_CONFIG: Embree refused the device configuration \"", config,
            "\"; valid is an Embree config string such as isa=sse2, isa=sse4.2, isa=avx, isa=avx2 or verbose=1"));
  if (!device) throw std::runtime_error("Embree: could not create a device" + addressSpaceNote());
}

EmbreeScene::~EmbreeScene() {
  release();
  if (device) rtcReleaseDevice(device);
}

void EmbreeScene::release() {
  if (rtcScene) rtcReleaseScene(rtcScene);
  rtcScene = nullptr;
}

void EmbreeScene::rebase(const glm::dvec3& newOrigin) {
  const std::lock_guard lock(rebaseMutex);
  if (rtcScene && newOrigin == origin) return;
  release();
  geometries.clear();
  origin = newOrigin;
  lights = shadingLights(*scene, origin);
  const double size = scene->bounds.empty() ? 0.0 : glm::length(scene->bounds.max - scene->bounds.min);
  scale = std::isfinite(size) && size > 0.0 ? std::exp2(std::round(std::log2(size))) : 1.0;
  rtcScene = rtcNewScene(device);
  rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);
  for (std::size_t k = 0; k < scene->instances.size(); ++k) {
    const Instance& instance = scene->instances[k];
    const Mesh& mesh = scene->meshes[static_cast<std::size_t>(instance.mesh)];
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* positions = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const glm::dvec3 p =
          (glm::dvec3(instance.worldFromModel * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0)) - origin) /
          scale;
      positions[i * 3] = static_cast<float>(p.x);
      positions[i * 3 + 1] = static_cast<float>(p.y);
      positions[i * 3 + 2] = static_cast<float>(p.z);
    }
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.indices.size() / 3));
    std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(rtcScene, geometry);
    rtcReleaseGeometry(geometry);
    const glm::dmat3 linear(instance.worldFromModel);
    if (id != geometries.size()) throw std::logic_error("Embree geometry IDs are not sequential");
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(linear[c][r]));
    const glm::mat3 tangentFromModel(largest > 0.0 && std::isfinite(largest) ? linear * (1.0 / largest) : linear);
    geometries.push_back({static_cast<int>(k), positions, glm::mat3(worldNormalFromModel(instance.worldFromModel)),
                          glm::determinant(linear) < 0.0, tangentFromModel});
  }
  rtcCommitScene(rtcScene);
}

glm::dvec3 EmbreeScene::originFor(const Camera& camera, ImageSize size) const {
  const glm::dvec3 lensCentre = lensRay(camera, {0.0, 0.0}, {0.5 * size.widthPx, 0.5 * size.heightPx}, size).origin;
  if (!finite(lensCentre))
    throw InputError(
        cat(camera.source, ": the camera's lens centre is not a finite point; check its VRP, VPN and PRP"));
  return scene->bounds.empty() ? lensCentre : glm::clamp(lensCentre, scene->bounds.min, scene->bounds.max);
}

InputError EmbreeScene::unfiniteRay(const Camera& camera, glm::dvec2 pixel) {
  return InputError(cat(camera.source, ": the camera gives rays that are not finite numbers at pixel ", pixel.x, ",",
                        pixel.y, "; check its window, PRP, focus and lens effects"));
}

}  // namespace lenslab
