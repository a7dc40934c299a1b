#include "raycast/RayCaster.h"

#include "camera/ImageMap.h"
#include "camera/Projection.h"
#include "camera/Ray.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/AperturePattern.h"
#include "raycast/AovRender.h"
#include "raycast/EmbreeScene.h"
#include "raycast/RenderLoop.h"
#include "raycast/TextureSampler.h"
#include "scene/ShadingLights.h"
#include "scene/MaterialMaps.h"

#include <embree3/rtcore.h>
#include <limits>

#include <algorithm>
#include <cmath>
#include <cstdint>
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

struct RayCaster::Impl : EmbreeScene {
  using EmbreeScene::EmbreeScene;
  std::vector<TextureSampler> samplers;       // by Scene texture index
  std::vector<TextureSampler> dataSamplers;   // the same, for textures read as data (linear); empty where none is

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

RayCaster::RayCaster(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {
  Impl& m = *impl_;
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
// AOVs' surface, textures over one pixel. (A template: the caster's Impl is private to RayCaster.)
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
  if (selection.instance) requireExactInstances(*impl_->scene);
  impl_->rebase(impl_->originFor(camera, size));
  const Impl& m = *impl_;
  // Green's ray from the lens centre: through the inverse lens model, so depth lines up with the image.
  const ThinLensMap map(camera, size);
  const glm::dvec3 axis = -viewBasis(camera.view).n;
  return aovImagesThrough(map, selection, [&](glm::dvec2 pixel) {
    const Impl::Hit hit = firstHit(m, map, pixel);
    const double depth = std::isinf(hit.t) ? hit.t : glm::dot(hit.t * hit.ray.direction, axis);
    return AovSurface{hit.surface, depth, hit.normal, hit.albedo, hit.gltfNode};
  });
}

Image RayCaster::render(const ImageMap& map, const RaycastOptions& options, const std::function<void(int, int)>& progress) const {
  impl_->rebase(impl_->originFor(map.camera(), map.size()));
  const Impl& m = *impl_;
  const auto shade = [&](const Ray& ray, const auto& rayAt, double footprintPx, glm::dvec2 pixel) {
    return m.shadeRay(ray, rayAt, footprintPx, map.camera(), pixel);
  };
  // The loop is compiled for each lens model the renderers have, so that its calls to the map are
  // direct (per ray, and per texture lookup for the ray differentials); another map goes through
  // the interface.
  const auto cast = [&](const auto& concrete) { return renderThroughMap(concrete, options, progress, m.origin, shade); };
  if (const auto* thin = dynamic_cast<const ThinLensMap*>(&map)) return cast(*thin);
  if (const auto* real = dynamic_cast<const RealLensMap*>(&map)) return cast(*real);
  return cast(map);
}

}  // namespace lenslab
