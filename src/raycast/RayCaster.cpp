#include "raycast/RayCaster.h"

#include "camera/ImageMap.h"
#include "camera/Projection.h"
#include "camera/Ray.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/AperturePattern.h"
#include "raycast/TextureSampler.h"
#include "scene/ShadingLights.h"
#include "scene/MaterialMaps.h"

#include <embree3/rtcore.h>
#include <limits>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

namespace lenslab {

namespace {

const Material kDefaultMaterial{};

// alphaMode BLEND surfaces composited along one ray at most; ones beyond are passed through.
constexpr int kMaxBlendLayers = 16;
// The AOVs describe the nearest surface at least this opaque (Cycles' pass alpha threshold):
// a faint blend surface leaves the AOVs to what lies behind it.
constexpr float kAovAlphaThreshold = 0.5f;

// Where a ray meets a triangle's plane, as barycentric (b1, b2) of its vertices p0, p1, p2.
glm::dvec2 barycentricOnPlane(const Ray& ray, const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
  const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
  const glm::dvec3 normal = glm::cross(e1, e2);
  const double denom = glm::dot(ray.direction, normal);
  const double t = std::abs(denom) > 0.0 ? glm::dot(p0 - ray.origin, normal) / denom : 0.0;
  const glm::dvec3 q = ray.origin + t * ray.direction - p0;
  const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const double d20 = glm::dot(q, e1), d21 = glm::dot(q, e2);
  const double det = d00 * d11 - d01 * d01;
  if (det == 0.0) return {0.0, 0.0};
  return {(d11 * d20 - d01 * d21) / det, (d00 * d21 - d01 * d20) / det};
}

}  // namespace

struct RayCaster::Impl {
  const Scene* scene = nullptr;
  RTCDevice device = nullptr;
  RTCScene rtcScene = nullptr;
  struct Geometry {
    int instance;
    const float* relativePositions;  // Embree's vertex buffer: 3 floats per vertex, (world − origin) / scale
    glm::mat3 normalFromModel;
    bool mirrored;
    glm::mat3 tangentFromModel;  // worldFromModel's linear part, scaled to its largest entry (scene.vert)
  };
  std::vector<Geometry> geometries;           // by Embree geometry ID
  std::vector<TextureSampler> samplers;       // by Scene texture index
  std::vector<ShadingLight> lights;           // positions relative to `origin` (rebase)
  std::vector<TextureSampler> dataSamplers;   // the same, for textures read as data (linear); empty where none is
  // Embree works in float. Its geometry is stored relative to `origin` (the point of the scene's
  // bounds nearest the camera's lens centre, subtracted in double), and each ray starts where it
  // enters the bounds: a scene 1e7 from the world origin, or a telephoto's subject 1e9 from the
  // camera, keeps the precision it has at the origin, float's relative error applying to sizes
  // within the scene and not to its distance from (0,0,0) or from the camera.
  glm::dvec3 origin{std::numeric_limits<double>::quiet_NaN()};
  // ... and in units of `scale` world units, a power of two near the scene's size, so that a scene
  // of 1e-12 or 1e-30 metres reaches Embree at the size of a metre: Embree runs with denormals
  // flushed to zero, and its triangle test multiplies edge by edge by edge (a 1e-13 scene already
  // underflows there). Scaling by a power of two rounds nothing; t values scale by it as well.
  double scale = 1.0;
  std::mutex rebaseMutex;

  ~Impl() {
    release();
    if (device) rtcReleaseDevice(device);
  }

  void release() {
    if (rtcScene) rtcReleaseScene(rtcScene);
    rtcScene = nullptr;
  }

  // (Re)builds the Embree scene with its geometry relative to `newOrigin`, unless it already is.
  void rebase(const glm::dvec3& newOrigin) {
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
      auto* positions = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                   3 * sizeof(float), mesh.vertices.size()));
      for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::dvec3 p = (glm::dvec3(instance.worldFromModel * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0)) - origin) / scale;
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

  // The origin the geometry is kept relative to for `camera`: the point of the bounds nearest its
  // lens centre (the lens centre itself when it is inside them).
  glm::dvec3 originFor(const Camera& camera, ImageSize size) const {
    const glm::dvec3 lensCentre = lensRay(camera, {0.0, 0.0}, {0.5 * size.widthPx, 0.5 * size.heightPx}, size).origin;
    if (!finite(lensCentre))
      throw InputError(cat(camera.source, ": the camera's lens centre is not a finite point; check its VRP, VPN and PRP"));
    return scene->bounds.empty() ? lensCentre : glm::clamp(lensCentre, scene->bounds.min, scene->bounds.max);
  }

  static bool finite(const glm::dvec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

  // Embree's RayK::valid(), which it asserts before tracing.
  static bool embreeTakes(const RTCRay& r) {
    constexpr float kLarge = 1.8e18f;  // Embree's FLT_LARGE is 1.844e18
    for (const float v : {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z})
      if (!(std::abs(v) <= kLarge)) return false;
    return r.tnear >= 0.0f && r.tnear <= r.tfar;
  }

  static InputError unfiniteRay(const Camera& camera, glm::dvec2 pixel) {
    return InputError(cat(camera.source, ": the camera gives rays that are not finite numbers at pixel ", pixel.x, ",", pixel.y,
                          "; check its window, PRP, focus and lens effects"));
  }

  // [enter, exit] of `ray` (relative to `origin`) through the scene's bounds, widened by a margin
  // so that a surface on a face of the box is never missed; empty (enter > exit) on a miss.
  std::pair<double, double> boundsSpan(const Ray& ray) const {
    const glm::dvec3 lo = scene->bounds.min - origin, hi = scene->bounds.max - origin;
    const double pad = 1e-4 * glm::length(hi - lo) + 1e-6 * glm::length(glm::abs(lo) + glm::abs(hi)) + 1e-30;
    double enter = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      const double o = ray.origin[a], d = ray.direction[a];
      if (d == 0.0) {
        if (o < lo[a] - pad || o > hi[a] + pad) return {1.0, 0.0};
        continue;
      }
      const double t0 = (lo[a] - pad - o) / d, t1 = (hi[a] + pad - o) / d;
      enter = std::max(enter, std::min(t0, t1));
      exit = std::min(exit, std::max(t0, t1));
    }
    return {enter, exit};
  }

  struct Hit {
    glm::vec3 color{0.0f};
    // Whether the AOVs see a surface (false: the background): the nearest one with alpha ≥
    // kAovAlphaThreshold, every opaque or masked surface counting as alpha 1. t, normal, albedo
    // and gltfNode are that surface's.
    bool surface = false;
    double t = std::numeric_limits<double>::infinity();  // along the unit ray direction
    Ray ray;
    // What the surface is, for the AOVs (unset on a miss): the normal it was shaded with (world,
    // unit), its base colour (linear RGB) and the glTF node of its instance.
    glm::vec3 normal{0.0f};
    glm::vec3 albedo{0.0f};
    int gltfNode = -1;
    // How much of the ray the surfaces cover (the image's alpha): 1 at an opaque surface, 0 on
    // the background, 1 − Π(1 − alpha) through blend surfaces onto the background.
    float coverage = 0.0f;
  };

  // The normal the surface is shaded with at barycentric (b0, b1, b2): the interpolated vertex
  // normal (the loader gives a mesh without normals its face normals) in world space, turned to
  // the viewer on the back of a double-sided material, as shaders/scene/scene.frag does. With a
  // normal map (`texel`: its linear RGB at the hit), the interpolated tangent frame turns it first,
  // by material_maps.glsl's mappedNormal as scene.frag does.
  static glm::vec3 shadingNormal(const Geometry& g, const Material& material, bool front, const Vertex& v0,
                                 const Vertex& v1, const Vertex& v2, float b0, float b1, float b2,
                                 const glm::vec3* texel = nullptr) {
    const glm::vec3 interpolated = g.normalFromModel * (b0 * v0.normal + b1 * v1.normal + b2 * v2.normal);
    glm::vec3 normal = glm::normalize(interpolated);
    if (texel) {
      const glm::vec4 t = b0 * v0.tangent + b1 * v1.tangent + b2 * v2.tangent;
      normal = mappedNormal(interpolated, g.tangentFromModel * glm::vec3(t), g.mirrored ? -t.w : t.w, *texel, material.normalScale);
    }
    if (material.doubleSided && !front) normal = -normal;
    return normal;
  }

  // First visible surface along `ray` (single-sided back faces and masked-out texels are passed
  // through, as the rasterizer culls and discards them), shaded. Surfaces of alphaMode BLEND in
  // front of it are composited over it front to back (docs/materials.md): each adds
  // transmittance · alpha · its shaded colour (emission included, so premultiplied by alpha as the
  // Khronos Sample Viewer blends it) and leaves transmittance · (1 − alpha) to what is behind; the
  // ray goes on from just past the blend surface (the skip masked texels take), kMaxBlendLayers
  // of them at most. Textures are filtered over `footprintPx` pixels: the part of the pixel this
  // sample stands for (see render), not the whole pixel, so that the mean of the samples converges
  // to the pixel integral of the unfiltered texture instead of to a pixel-blurred one. The returned ray is relative to `origin`.
  // `inverseFocusShift` focuses the ray for one colour or one radius (viewThroughLens).
  Hit shadeAlong(const Camera& camera, glm::dvec2 lensOffset, glm::dvec2 pixel, ImageSize size, double footprintPx,
                 double inverseFocusShift = 0.0) const {
    Ray ray = lensRay(camera, lensOffset, pixel, size, inverseFocusShift);
    ray.origin -= origin;
    // The barrel's opening (cat's-eye vignetting): a ray it stops brings no light, background included.
    // With lens effects `pixel` is already the true perspective position (render's
    // undistortedSample: the distorted film point taken back through the inverse lens model, per
    // channel) and `inverseFocusShift` that channel's and that radius's plane of focus. The
    // lecture's thin lens deflects the ray from aperture point p toward the point of the plane of
    // focus seen in the undistorted direction n; that ray is the one the barrel may stop, at
    // p·(1 − L/z_f) + L·n. Distortion and lateral colour only move where on the film that ray
    // lands, so the test takes n of the undistorted position, never the distorted film point, and
    // z_f with the channel's and the curvature's shift (the same ray lensRay casts).
    if (camera.hasBarrel()) {
      const glm::dvec2 w = windowFromPixel(camera.view.window, pixel, size.widthPx, size.heightPx);
      const glm::dvec2 normalised = (w - glm::dvec2(camera.view.prp)) / camera.view.prp.z;
      if (!throughBarrel(camera.barrel, lensOffset, normalised, camera.inverseFocusDistance() + inverseFocusShift))
        return Hit{glm::vec3(0.0f), false, std::numeric_limits<double>::infinity(), ray};
    }
    // The texture's ray differentials: the same lens point, the pixel one footprint over.
    const auto rayAt = [&](glm::dvec2 offset) {
      Ray r = lensRay(camera, lensOffset, pixel + offset, size, inverseFocusShift);
      r.origin -= origin;
      return r;
    };
    return shadeRay(ray, rayAt, footprintPx, camera, pixel);
  }

  // What `ray` (relative to `origin`) sees: the surfaces it meets shaded, blend ones composited
  // front to back, or the background. `rayAt(offset)` is the same sample's ray from the pixel
  // `offset` over (relative to `origin`): textures filter over the footprint those rays span.
  // `camera` and `pixel` name the ray in messages.
  template <class RayAt>
  Hit shadeRay(const Ray& ray, const RayAt& rayAt, double footprintPx, const Camera& camera, glm::dvec2 pixel) const {
    Hit miss{scene->lighting.background, false, std::numeric_limits<double>::infinity(), ray};
    // Checked here, not left to Embree's assertions: no input may reach an abort.
    // A direction that normalised to zero (its length overflowed) counts as not finite.
    if (!finite(ray.origin) || !(std::abs(glm::length(ray.direction) - 1.0) < 1e-6) || std::isnan(ray.tNear) ||
        std::isnan(ray.tFar))
      throw unfiniteRay(camera, pixel);
    // The environment, where there is one, is what a ray that hits nothing sees: at infinity, so
    // only the ray's direction picks it (shaders/common/environment.glsl, as the rasterizer's).
    if (scene->environment) miss.color = scene->environment->background(glm::vec3(ray.direction));
    // Embree's ray starts where this one enters the scene's bounds (in double), so that its float
    // origin is within the scene's size of `origin` however far away the camera stands; a start
    // before the PRP (a parallel projection's negative near) is fine there too.
    const auto [enter, exit] = boundsSpan(ray);
    const double tEnd = std::min(ray.tFar, exit);
    if (!(enter <= exit) || !(std::max(ray.tNear, enter) <= tEnd)) return miss;
    const double tStart = std::max(ray.tNear, enter);
    const glm::dvec3 start = (ray.origin + tStart * ray.direction) / scale;  // in Embree's units
    double tNear = ray.tNear;
    glm::vec3 blended(0.0f);     // Σ transmittance · alpha · colour over the blend surfaces so far
    float transmittance = 1.0f;  // Π (1 − alpha) over them
    int blendLayers = 0;
    std::optional<Hit> aovSurface;  // the nearest blend surface with alpha ≥ kAovAlphaThreshold
    // What lies behind the blend surfaces (an opaque surface, or the background) under them.
    const auto behind = [&](Hit last, bool opaque) {
      if (blendLayers == 0) {
        last.coverage = opaque ? 1.0f : 0.0f;
        return last;
      }
      const glm::vec3 color = blended + transmittance * last.color;
      Hit out = aovSurface ? *aovSurface : last;
      out.color = color;
      out.coverage = opaque ? 1.0f : 1.0f - transmittance;
      return out;
    };
    for (int layer = 0; layer < 64; ++layer) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rh{};
      rh.ray.org_x = static_cast<float>(start.x);
      rh.ray.org_y = static_cast<float>(start.y);
      rh.ray.org_z = static_cast<float>(start.z);
      rh.ray.dir_x = static_cast<float>(ray.direction.x);
      rh.ray.dir_y = static_cast<float>(ray.direction.y);
      rh.ray.dir_z = static_cast<float>(ray.direction.z);
      rh.ray.tnear = static_cast<float>(std::max(0.0, tNear - tStart) / scale);
      rh.ray.tfar = std::isinf(tEnd) ? std::numeric_limits<float>::infinity() : static_cast<float>((tEnd - tStart) / scale);
      if (!(rh.ray.tnear <= rh.ray.tfar)) return behind(miss, false);
      // Embree asserts (aborts) on a ray it cannot take: every float finite and below 1.8e18.
      if (!embreeTakes(rh.ray)) throw unfiniteRay(camera, pixel);
      rh.ray.mask = 0xFFFFFFFFu;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(rtcScene, &context, &rh);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return behind(miss, false);

      const Geometry& g = geometries[rh.hit.geomID];
      const Instance& instance = scene->instances[static_cast<std::size_t>(g.instance)];
      const Mesh& mesh = scene->meshes[static_cast<std::size_t>(instance.mesh)];
      const Material& material = mesh.material >= 0 ? scene->materials[static_cast<std::size_t>(mesh.material)] : kDefaultMaterial;
      const std::uint32_t i0 = mesh.indices[rh.hit.primID * 3], i1 = mesh.indices[rh.hit.primID * 3 + 1],
                          i2 = mesh.indices[rh.hit.primID * 3 + 2];
      auto world = [&](std::uint32_t i) {  // relative to `origin`, as the ray is
        return scale * glm::dvec3(g.relativePositions[i * 3], g.relativePositions[i * 3 + 1], g.relativePositions[i * 3 + 2]);
      };
      const glm::dvec3 p0 = world(i0), p1 = world(i1), p2 = world(i2);
      // Front-facing as GL decides it: counter-clockwise on screen, i.e. the model's winding seen
      // from the normal's side; a mirroring transform turns it around (glFrontFace(GL_CW)).
      bool front = glm::dot(glm::cross(p1 - p0, p2 - p0), ray.direction) < 0.0;
      if (g.mirrored) front = !front;
      const double hitAfterStart = scale * static_cast<double>(rh.ray.tfar);
      const double tHit = tStart + hitAfterStart;
      // Past this surface, measured from Embree's start (a skip relative to the camera's distance
      // would jump a telephoto's whole subject).
      const double skipTo = tStart + hitAfterStart * (1.0 + 1e-6) + 1e-9 * scale;
      if (!front && !material.doubleSided) {
        tNear = skipTo;
        continue;
      }
      const float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
      const Vertex& v0 = mesh.vertices[i0];
      const Vertex& v1 = mesh.vertices[i1];
      const Vertex& v2 = mesh.vertices[i2];
      // A texture of this surface at the hit, filtered over the sample's footprint by ray
      // differentials: the same lens point, one footprint over in x and in y.
      const glm::vec2 uv0 = b0 * v0.uv + b1 * v1.uv + b2 * v2.uv, uv1 = b0 * v0.uv1 + b1 * v1.uv1 + b2 * v2.uv1;
      // Each texture reference samples its own uv set through its uv transform (slotUv, as
      // scene.frag); the footprint's derivatives go through the same transform, so a scaled uv
      // widens the footprint as GL's derivatives of the transformed uv do.
      const auto sampleTexture = [&](const TextureRef& ref, bool data = false) {
        auto uvAt = [&](glm::dvec2 offset) {
          const Ray r = rayAt(offset);
          const glm::dvec2 b = barycentricOnPlane(r, p0, p1, p2);
          const auto at = [&](glm::vec2 Vertex::*set) {
            return glm::vec2((1.0 - b.x - b.y) * glm::dvec2(v0.*set) + b.x * glm::dvec2(v1.*set) + b.y * glm::dvec2(v2.*set));
          };
          return slotUv(at(&Vertex::uv), at(&Vertex::uv1), ref.texCoord, ref.uvFromTexCoord);
        };
        const glm::vec2 uvHere = uvAt({0.0, 0.0});
        const auto index = static_cast<std::size_t>(ref.texture);
        const Texture& texture = scene->textures[index];
        return (data ? dataSamplers : samplers)[index].sample(texture.sampler, slotUv(uv0, uv1, ref.texCoord, ref.uvFromTexCoord),
                                                              uvAt({footprintPx, 0.0}) - uvHere, uvAt({0.0, footprintPx}) - uvHere);
      };
      glm::vec4 base = material.baseColorFactor * (b0 * v0.color + b1 * v1.color + b2 * v2.color);
      if (material.baseColorTexture.present()) base *= sampleTexture(material.baseColorTexture);
      if (material.alphaMode == AlphaMode::Mask && base.a < material.alphaCutoff) {
        tNear = skipTo;
        continue;
      }
      const bool blend = material.alphaMode == AlphaMode::Blend;
      if (blend && blendLayers >= kMaxBlendLayers) {
        tNear = skipTo;
        continue;
      }
      const bool normalMapped = material.normalTexture.present() && mesh.hasTangents;
      const glm::vec3 normalTexel = normalMapped ? glm::vec3(sampleTexture(material.normalTexture, true)) : glm::vec3(0.0f);
      const glm::vec3 normal = shadingNormal(g, material, front, v0, v1, v2, b0, b1, b2, normalMapped ? &normalTexel : nullptr);
      glm::vec3 colour(base);
      if (!material.unlit) {
        // brdf.glsl, as scene.frag evaluates it: the same inputs, v toward this ray's origin.
        ShadingSurface surface;
        surface.baseColor = glm::vec3(base);
        surface.metallic = material.metallicFactor;
        surface.perceptualRoughness = material.roughnessFactor;
        if (material.metallicRoughnessTexture.present()) {
          const glm::vec4 mr = sampleTexture(material.metallicRoughnessTexture, true);
          surface.perceptualRoughness *= mr.g;
          surface.metallic *= mr.b;
        }
        if (material.occlusionTexture.present())
          surface.occlusion = 1.0f + material.occlusionStrength * (sampleTexture(material.occlusionTexture, true).r - 1.0f);
        surface.n = normal;
        surface.v = -glm::vec3(ray.direction);
        const glm::vec3 position(ray.origin + tHit * ray.direction);  // relative to `origin`, as the lights are
        colour = glm::vec3(0.0f);
        for (const ShadingLight& light : lights) colour += punctualRadiance(surface, light, position);
        // Light from all around: the environment, prefiltered (environment.glsl), or the uniform
        // surround (Lighting::ambient), as scene.frag's shadeLit.
        glm::vec3 ambientDiffuse(scene->lighting.ambient), ambientSpecular(scene->lighting.ambient);
        if (scene->environment) {
          ambientDiffuse = scene->environment->diffuse(surface.n);
          ambientSpecular = scene->environment->specular(specularDominantDirection(surface.n, surface.v, surface.perceptualRoughness), surface.perceptualRoughness);
        }
        const glm::vec3 dfg = dfgLookup(glm::dot(surface.n, surface.v), surface.perceptualRoughness);
        colour += imageLightRadiance(surface, ambientDiffuse, ambientSpecular, dfg);
      }
      if (material.emits()) {
        glm::vec3 emitted = material.emissive;
        if (material.emissiveTexture.present()) emitted *= glm::vec3(sampleTexture(material.emissiveTexture));
        colour += emitted;
      }
      const Hit here{colour, true, tHit, ray, normal, glm::vec3(base), instance.gltfNode};
      if (blend) {
        // Straight alpha, as scene.frag's ALPHA_BLEND writes it (clamped: GL does not clamp a
        // float target's blend factors).
        const float alpha = std::clamp(base.a, 0.0f, 1.0f);
        blended += transmittance * alpha * colour;
        transmittance *= 1.0f - alpha;
        ++blendLayers;
        if (!aovSurface && alpha >= kAovAlphaThreshold) aovSurface = here;
        if (transmittance <= 0.0f) return behind(Hit{glm::vec3(0.0f), false, tHit, ray}, true);  // nothing behind shows
        tNear = skipTo;
        continue;
      }
      return behind(here, true);
    }
    return behind(miss, false);
  }
};

RayCaster::RayCaster(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.scene = &scene;
  // LENSLAB_EMBREE_CONFIG is passed to Embree as its device configuration ("isa=sse2",
  // "isa=avx", "verbose=1", ...): it forces another SIMD path for the ray caster, so a test can show
  // that its figures do not hang on the ISA this CPU picks (docs/stability.md).
  const char* config = std::getenv("LENSLAB_EMBREE_CONFIG");
  m.device = rtcNewDevice(config && *config ? config : nullptr);
  if (!m.device && config && *config)
    throw InputError(cat("LENSLAB_EMBREE_CONFIG: Embree refused the device configuration \"", config,
                         "\"; valid is an Embree config string such as isa=sse2, isa=sse4.2, isa=avx, isa=avx2 or verbose=1"));
  if (!m.device) throw std::runtime_error("Embree: could not create a device");
  // The Embree scene is built on first use, relative to that camera (rebase): building it here too
  // would build it twice for every render.
  // Mip chains where the GPU makes them: any sampler of the image minifies with mipmaps.
  // Textures that a material reads as data (a normal map) get a linear copy as well, as GpuScene
  // stores their images as GL_RGBA8.
  std::vector<bool> asData(scene.textures.size(), false);
  for (const Material& material : scene.materials)
    for (const TextureRef* ref : {&material.normalTexture, &material.metallicRoughnessTexture, &material.occlusionTexture})
      if (ref->present()) asData[static_cast<std::size_t>(ref->texture)] = true;
  m.dataSamplers.resize(scene.textures.size());
  for (std::size_t i = 0; i < scene.textures.size(); ++i) {
    const Texture& t = scene.textures[i];
    const bool mipmaps = t.sampler.minFilter != Filter::Nearest && t.sampler.minFilter != Filter::Linear;
    m.samplers.emplace_back(scene.images[static_cast<std::size_t>(t.image)], mipmaps);
    if (asData[i]) m.dataSamplers[i] = TextureSampler(scene.images[static_cast<std::size_t>(t.image)], mipmaps, false);
  }
}

RayCaster::~RayCaster() = default;

glm::vec3 RayCaster::trace(const Camera& camera, glm::dvec2 lensOffset, glm::dvec2 pixel, ImageSize size,
                           double footprintPx) const {
  impl_->rebase(impl_->originFor(camera, size));
  return impl_->shadeAlong(camera, lensOffset, pixel, size, footprintPx).color;
}

double RayCaster::depthAt(const Camera& camera, glm::dvec2 pixel, ImageSize size) const {
  impl_->rebase(impl_->originFor(camera, size));
  const Impl::Hit hit = impl_->shadeAlong(camera, {0.0, 0.0}, pixel, size, 1.0);
  if (std::isinf(hit.t)) return hit.t;
  return -glm::dot(hit.t * hit.ray.direction, viewBasis(camera.view).n);
}

std::vector<float> RayCaster::depthImage(const Camera& camera, ImageSize size) const {
  AovSelection depth;
  depth.depth = true;
  return aovImages(camera, size, depth).depth;
}

namespace {

// What the ray of `map` through film point `pixel` from the lens centre (green's) sees first: the
// AOVs' surface. Textures filtered over one pixel. (A template over the caster's Impl, which is
// private to RayCaster.)
template <class Impl>
auto firstHit(const Impl& m, const ImageMap& map, glm::dvec2 pixel) {
  using Hit = typename Impl::Hit;
  const std::optional<CameraRay> r = map.ray(pixel, {0.0, 0.0}, 1);
  Ray ray = r ? r->ray : Ray{};
  ray.origin -= m.origin;
  if (!r || r->blocked) return Hit{glm::vec3(0.0f), false, std::numeric_limits<double>::infinity(), ray};
  const auto rayAt = [&](glm::dvec2 offset) {
    Ray n = map.footprintRay(*r, offset);
    n.origin -= m.origin;
    return n;
  };
  return m.shadeRay(ray, rayAt, 1.0, map.camera(), r->pixel);
}

}  // namespace

AovImages RayCaster::aovImages(const Camera& camera, ImageSize size, const AovSelection& selection) const {
  AovImages out;
  out.widthPx = size.widthPx;
  out.heightPx = size.heightPx;
  const auto pixels = static_cast<std::size_t>(size.pixelCount());
  if (selection.depth) out.depth.resize(pixels);
  if (selection.normal) out.normal.resize(3 * pixels);
  if (selection.albedo) out.albedo.resize(3 * pixels);
  if (selection.instance) {
    out.instance.resize(pixels);
    // Float holds every integer to 2^24 exactly, and skips odd ones beyond.
    for (const Instance& instance : impl_->scene->instances)
      if (instance.gltfNode > kMaxExactInstance)
        throw InputError(cat(impl_->scene->source, ": node ", instance.gltfNode, " has an index beyond 2^24 = ",
                             kMaxExactInstance, ", the largest the float instance AOV holds exactly"));
  }
  impl_->rebase(impl_->originFor(camera, size));
  const Impl& m = *impl_;
  const ViewBasis basis = viewBasis(camera.view);
  const glm::dvec3 axis = -basis.n;
  // Green's ray from the lens centre: through the inverse lens model, so depth lines up with the image.
  const ThinLensMap map(camera, size);
  tbb::parallel_for(tbb::blocked_range<int>(0, size.heightPx), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < size.widthPx; ++x) {
        const Impl::Hit hit = firstHit(m, map, {x + 0.5, y + 0.5});
        const std::size_t i = static_cast<std::size_t>(y) * size.widthPx + x;
        if (selection.depth)
          out.depth[i] = std::isinf(hit.t) ? std::numeric_limits<float>::infinity()
                                           : static_cast<float>(glm::dot(hit.t * hit.ray.direction, axis));
        if (selection.normal && hit.surface) {
          // Camera space: the world normal's components along u, v and n.
          const glm::dvec3 n(hit.normal);
          const glm::dvec3 cameraNormal(glm::dot(n, basis.u), glm::dot(n, basis.v), glm::dot(n, basis.n));
          for (int k = 0; k < 3; ++k) out.normal[3 * i + k] = static_cast<float>(cameraNormal[k]);
        }
        if (selection.albedo && hit.surface)
          for (int k = 0; k < 3; ++k) out.albedo[3 * i + k] = hit.albedo[k];
        if (selection.instance)
          out.instance[i] = hit.surface ? static_cast<float>(hit.gltfNode) : kNoSurfaceInstance;
      }
  });
  return out;
}

namespace {

// Rows in bands of 16, each band's rows spread over the cores by TBB; `progress` between bands,
// from the calling thread.
template <class Rows>
void inBands(ImageSize size, const std::function<void(int, int)>& progress, const Rows& rows) {
  constexpr int kBand = 16;
  for (int band = 0; band < size.heightPx; band += kBand) {
    const int end = std::min(band + kBand, size.heightPx);
    tbb::parallel_for(tbb::blocked_range<int>(band, end), [&](const tbb::blocked_range<int>& r) { rows(r.begin(), r.end()); });
    if (progress) progress(end, size.heightPx);
  }
}

// The lens points of a pixel's samples in the map's domain: the stratified sample's point of the
// unit disk (Shirley–Chiu concentric), or for a box around a real lens's exit pupil points of the
// R2 sequence with a random rotation per pixel (Cranley–Patterson): evenly spread over the box for
// any count, and unbiased.
class LensPoints {
 public:
  LensPoints(LensDomain domain, std::uint32_t seed) : square_(domain == LensDomain::Square) {
    if (square_) rotation_ = glm::dvec2(makeApertureSamples(AperturePattern::Random, 1, seed ^ 0x9e3779b9u)[0].pixel) + 0.5;
  }
  glm::dvec2 at(const LensSample& s, std::size_t i) const {
    if (!square_) return s.lens;
    constexpr double kPlastic = 1.32471795724474602596;
    const glm::dvec2 step(1.0 / kPlastic, 1.0 / (kPlastic * kPlastic));
    return glm::fract(rotation_ + static_cast<double>(i + 1) * step);
  }

 private:
  bool square_;
  glm::dvec2 rotation_{0.0};
};

// A different stratified set per pixel, so that the noise does not repeat across pixels.
std::uint32_t pixelSeed(std::uint32_t seed, int x, int y, int widthPx) {
  return seed * 2654435761u ^ static_cast<std::uint32_t>(std::int64_t{y} * widthPx + x) * 40503u;
}

}  // namespace

Image RayCaster::render(const Camera& camera, ImageSize size, const RaycastOptions& options,
                        const std::function<void(int, int)>& progress) const {
  return render(ThinLensMap(camera, size), options, progress);
}

Image RayCaster::render(const LensCamera& lens, const Camera& camera, ImageSize size, const RaycastOptions& options,
                        const std::function<void(int, int)>& progress) const {
  return render(RealLensMap(lens, camera, size), options, progress);
}

Image RayCaster::render(const ImageMap& map, const RaycastOptions& options, const std::function<void(int, int)>& progress) const {
  const ImageSize size = map.size();
  Image image(size.widthPx, size.heightPx);
  const int spp = std::max(1, options.samplesPerPixel);
  impl_->rebase(impl_->originFor(map.camera(), size));
  const Impl& m = *impl_;
  // The samples' pixel positions are stratified, one stratum of 1/√spp × 1/√spp pixels each: that
  // is the area a sample stands for, so its texture lookups filter over that and no more.
  const double footprintPx = 1.0 / std::sqrt(static_cast<double>(spp));
  const int channels = map.rayChannels();
  inBands(size, progress, [&](int yBegin, int yEnd) {
    for (int y = yBegin; y < yEnd; ++y)
      for (int x = 0; x < size.widthPx; ++x) {
        const std::uint32_t seed = pixelSeed(options.seed, x, y, size.widthPx);
        const auto samples = makeApertureSamples(AperturePattern::Concentric, spp, seed);
        const LensPoints lens(map.lensDomain(), seed);
        // A map that solves an inverse per film point starts each sample's from the pixel centre's.
        std::optional<CameraRay> centre[3];
        if (map.startsFromCentre())
          for (int c = 0; c < channels; ++c) centre[c] = map.ray({x + 0.5, y + 0.5}, {0.0, 0.0}, channels == 3 ? c : 1);
        glm::dvec3 sum(0.0);
        double covered = 0.0, weights = 0.0;  // Σ coverage (Hit::coverage) and Σ weight of the rays: alpha is their ratio
        for (std::size_t i = 0; i < samples.size(); ++i) {
          const glm::dvec2 pixel(x + 0.5 + samples[i].pixel.x, y + 0.5 + samples[i].pixel.y);
          for (int c = 0; c < channels; ++c) {
            const std::optional<CameraRay> r = map.ray(pixel, lens.at(samples[i], i), channels == 3 ? c : 1, centre[c] ? &*centre[c] : nullptr);
            if (!r) continue;  // outside what the lens passes: no light, and no part of the pixel's coverage
            weights += r->weight / channels;
            if (r->blocked) continue;  // the barrel stops it: no light, background included
            Ray ray = r->ray;
            ray.origin -= m.origin;
            // The texture's ray differentials: the same lens point, the film point one footprint over.
            const auto rayAt = [&](glm::dvec2 offset) {
              Ray n = map.footprintRay(*r, offset);
              n.origin -= m.origin;
              return n;
            };
            const Impl::Hit hit = m.shadeRay(ray, rayAt, footprintPx, map.camera(), r->pixel);
            if (channels == 3) sum[c] += r->weight * hit.color[c];
            else sum += r->weight * glm::dvec3(hit.color);
            covered += r->weight * hit.coverage / channels;
          }
        }
        const double n = static_cast<double>(samples.size());
        image.set(x, y, glm::vec4(glm::vec3(map.gainAt({x + 0.5, y + 0.5}) * sum / n),
                                  static_cast<float>(weights > 0.0 ? covered / weights : 0.0)));
      }
  });
  return image;
}

}  // namespace lenslab
