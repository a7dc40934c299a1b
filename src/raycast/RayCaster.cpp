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
#include "raycast/SurfaceInputs.h"
#include "raycast/TextureSampler.h"
#include "scene/ShadingLights.h"

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

// Surfaces followed along one ray at most (blend surfaces composited, back faces and masked texels
// passed through, then the surface that stops it). Every blend surface is composited, as the
// raster composites every one; a ray that meets more surfaces than this is refused in one line
// naming its pixel, not cut short in silence.
constexpr int kMaxSurfacesPerRay = 4096;

InputError tooManySurfaces(const std::string& scene, glm::dvec2 pixel) {
  return InputError(cat(scene, ": more than ", kMaxSurfacesPerRay, " surfaces lie along the ray at pixel ", pixel.x,
                        ",", pixel.y,
                        " (blend layers, back faces and cut-out texels); the ray caster follows at most that many"));
}
// The AOVs describe the nearest surface at least this opaque (Cycles' pass alpha threshold):
// a faint blend surface leaves the AOVs to what lies behind it.
constexpr float kAovAlphaThreshold = 0.5f;

}  // namespace

struct RayCaster::Impl : EmbreeScene {
  using EmbreeScene::EmbreeScene;
  std::vector<TextureSampler> samplers;      // by Scene texture index
  std::vector<TextureSampler> dataSamplers;  // the same, for textures read as data (linear); empty where none is

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

  // What the ray `map` casts from film point `pixel` through lens sample `lens` for `channel`
  // sees (shadeRay), textures filtered over `footprintPx` pixels by the map's footprint rays. A
  // ray the lens does not pass (outside a real lens's stop or rims), or that the thin lens's
  // barrel stops, brings no light and sees no surface, background included. The returned ray is
  // relative to `origin`.
  Hit shadeAlong(const ImageMap& map, glm::dvec2 pixel, glm::dvec2 lens, int channel, double footprintPx) const {
    return shadeCameraRay(map, map.ray(pixel, lens, channel), footprintPx);
  }

  // shadeAlong for a ray the map has cast (nullopt: one the lens does not pass).
  Hit shadeCameraRay(const ImageMap& map, const std::optional<CameraRay>& r, double footprintPx) const {
    Ray ray = r ? r->ray : Ray{};
    ray.origin -= origin;
    if (!r || r->blocked) return Hit{glm::vec3(0.0f), false, std::numeric_limits<double>::infinity(), ray};
    // The texture's ray differentials: the same lens point, the film point one footprint over.
    const auto rayAt = [&](glm::dvec2 offset) {
      Ray n = map.footprintRay(*r, offset);
      n.origin -= origin;
      return n;
    };
    return shadeRay(ray, rayAt, footprintPx, map.camera(), r->pixel);
  }

  // The nearest hit along the ray from `start` (in Embree's units) along `direction`, between
  // tNear and tEnd (along the caller's ray, whose tStart is `start`); none on a miss.
  std::optional<RTCRayHit> intersect(const glm::dvec3& start, const glm::dvec3& direction, double tNear, double tStart,
                                     double tEnd, const Camera& camera, glm::dvec2 pixel) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(start.x);
    rh.ray.org_y = static_cast<float>(start.y);
    rh.ray.org_z = static_cast<float>(start.z);
    rh.ray.dir_x = static_cast<float>(direction.x);
    rh.ray.dir_y = static_cast<float>(direction.y);
    rh.ray.dir_z = static_cast<float>(direction.z);
    rh.ray.tnear = static_cast<float>(std::max(0.0, tNear - tStart) / scale);
    rh.ray.tfar =
        std::isinf(tEnd) ? std::numeric_limits<float>::infinity() : static_cast<float>((tEnd - tStart) / scale);
    if (!(rh.ray.tnear <= rh.ray.tfar)) return std::nullopt;
    // Embree asserts (aborts) on a ray it cannot take: every float finite and below 1.8e18.
    if (!embreeTakes(rh.ray)) throw unfiniteRay(camera, pixel);
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rtcScene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return rh;
  }

  // The triangle `rh` hit: its vertices, its corners relative to `origin` (as the rays are) and
  // Embree's barycentric coordinates of the hit.
  HitTriangle hitTriangle(const Geometry& g, const Mesh& mesh, const RTCRayHit& rh) const {
    HitTriangle t;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh.indices[rh.hit.primID * 3 + static_cast<unsigned>(k)];
      t.vertices[static_cast<std::size_t>(k)] = &mesh.vertices[i];
      t.corners[static_cast<std::size_t>(k)] =
          scale *
          glm::dvec3(g.relativePositions[i * 3], g.relativePositions[i * 3 + 1], g.relativePositions[i * 3 + 2]);
    }
    const float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
    t.b = {b0, b1, b2};
    return t;
  }

  // A hit as the shading leaves it: what it sends toward the ray's origin, its shading normal,
  // base colour (the albedo AOV's) and blend alpha.
  struct ShadedHit {
    glm::vec3 radiance{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 albedo{0.0f};
    float alpha = 1.0f;
  };

  // The hit shaded as scene.frag shades a fragment (shade_surface.glsl), its textures filtered over
  // the sample's footprint by ray differentials (the same lens point, one footprint over in x and
  // in y; see shadeRay); nothing where alphaMode MASK cuts it out.
  template <class RayAt>
  std::optional<ShadedHit> shadeHit(const Geometry& g, const Mesh& mesh, const Material& material,
                                    const HitTriangle& triangle, bool front, const Ray& ray, double tHit,
                                    const RayAt& rayAt, double footprintPx) const {
    const SurfaceMaterial surface = surfaceMaterial(material, mesh.hasTangents);
    const TextureFootprint footprint =
        readsTextures(surface) ? textureFootprint(triangle, ray, rayAt, footprintPx) : TextureFootprint{};
    const HitFetch fetch(*scene, material, samplers, dataSamplers, triangle, footprint);
    SurfacePoint point =
        surfacePoint(triangle, g.normalFromModel, g.tangentFromModel, g.mirrored, surface.normalMapped);
    const glm::vec4 base = surfaceBaseColor(surface, point.vertexColor, fetch);
    if (alphaCutOut(surface, base)) return std::nullopt;
    point.frontFacing = front;
    point.position = glm::vec3(ray.origin + tHit * ray.direction);  // relative to `origin`, as the lights are
    point.towardViewer = -glm::vec3(ray.direction);
    const SurfaceLighting lighting{lights, scene->lighting.ambient, scene->environment != nullptr};
    const ShadedSurface shaded = shadeSurface(surface, base, point, lighting, fetch);
    return ShadedHit{shaded.radiance, shaded.normal, glm::vec3(base), shaded.alpha};
  }

  // What `ray` (relative to `origin`) sees: the first visible surface along it (single-sided back
  // faces and masked-out texels are passed through, as the rasterizer culls and discards them),
  // shaded, or the background. Surfaces of alphaMode BLEND in front of it are composited over it
  // front to back (docs/materials.md): each adds transmittance · alpha · its shaded colour
  // (emission included, so premultiplied by alpha as the Khronos Sample Viewer blends it) and
  // leaves transmittance · (1 − alpha) to what is behind; the ray goes on from just past the blend
  // surface (the skip masked texels take), every one of them. `rayAt(offset)` is the
  // same sample's ray from the pixel `offset` over (relative to `origin`): textures filter over the
  // footprint those rays span, `footprintPx` pixels, the part of the pixel this sample stands for
  // (see render), not the whole pixel, so that the mean of the samples converges to the pixel
  // integral of the unfiltered texture instead of to a pixel-blurred one. `camera` and `pixel` name
  // the ray in messages.
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
    for (int surface = 0;; ++surface) {
      if (surface == kMaxSurfacesPerRay) throw tooManySurfaces(scene->source, pixel);
      const std::optional<RTCRayHit> rh = intersect(start, ray.direction, tNear, tStart, tEnd, camera, pixel);
      if (!rh) return behind(miss, false);
      const Geometry& g = geometries[rh->hit.geomID];
      const Instance& instance = scene->instances[static_cast<std::size_t>(g.instance)];
      const Mesh& mesh = scene->meshes[static_cast<std::size_t>(instance.mesh)];
      const Material& material =
          mesh.material >= 0 ? scene->materials[static_cast<std::size_t>(mesh.material)] : kDefaultMaterial;
      const HitTriangle triangle = hitTriangle(g, mesh, *rh);
      const auto& [p0, p1, p2] = triangle.corners;
      // Front-facing as GL decides it: counter-clockwise on screen, i.e. the model's winding seen
      // from the normal's side; a mirroring transform turns it around (glFrontFace(GL_CW)).
      bool front = glm::dot(glm::cross(p1 - p0, p2 - p0), ray.direction) < 0.0;
      if (g.mirrored) front = !front;
      const double hitAfterStart = scale * static_cast<double>(rh->ray.tfar);
      const double tHit = tStart + hitAfterStart;
      // Past this surface, measured from Embree's start (a skip relative to the camera's distance
      // would jump a telephoto's whole subject).
      const double skipTo = tStart + hitAfterStart * (1.0 + 1e-6) + 1e-9 * scale;
      const bool blend = material.alphaMode == AlphaMode::Blend;
      // Passed through: a single-sided back face (the rasterizer culls it), and a texel alphaMode
      // MASK cuts out (shadeHit).
      std::optional<ShadedHit> shaded;
      if (front || material.doubleSided)
        shaded = shadeHit(g, mesh, material, triangle, front, ray, tHit, rayAt, footprintPx);
      if (!shaded) {
        tNear = skipTo;
        continue;
      }
      const Hit here{shaded->radiance, true, tHit, ray, shaded->normal, shaded->albedo, instance.gltfNode};
      if (blend) {
        // Straight alpha, as scene.frag's ALPHA_BLEND writes it.
        const float alpha = shaded->alpha;
        blended += transmittance * alpha * shaded->radiance;
        transmittance *= 1.0f - alpha;
        ++blendLayers;
        if (!aovSurface && alpha >= kAovAlphaThreshold) aovSurface = here;
        if (transmittance <= 0.0f) return behind(Hit{glm::vec3(0.0f), false, tHit, ray}, true);  // nothing behind shows
        tNear = skipTo;
        continue;
      }
      return behind(here, true);
    }
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
    for (const TextureRef* ref :
         {&material.normalTexture, &material.metallicRoughnessTexture, &material.occlusionTexture})
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

glm::vec3 RayCaster::trace(const ImageMap& map, glm::dvec2 pixel, glm::dvec2 lens, int channel,
                           double footprintPx) const {
  impl_->rebase(impl_->originFor(map.camera(), map.size()));
  return impl_->shadeAlong(map, pixel, lens, channel, footprintPx).color;
}

double RayCaster::depthAt(const Camera& camera, glm::dvec2 pixel, ImageSize size) const {
  impl_->rebase(impl_->originFor(camera, size));
  // `pixel` is already a true perspective position (camera/FocusOnPixel.h takes the output's back
  // through the lens model): the ray is the pinhole view's, the effects left out.
  const Impl::Hit hit = impl_->shadeAlong(ThinLensMap::truePerspective(camera, size), pixel, {0.0, 0.0}, 1, 1.0);
  if (std::isinf(hit.t)) return hit.t;
  return -glm::dot(hit.t * hit.ray.direction, viewBasis(camera.view).n);
}

std::vector<float> RayCaster::depthImage(const Camera& camera, ImageSize size) const {
  AovSelection depth;
  depth.depth = true;
  return aovImages(camera, size, depth).depth;
}

AovImages RayCaster::aovImages(const Camera& camera, ImageSize size, const AovSelection& selection) const {
  return aovImages(ThinLensMap(camera, size), selection);
}

AovImages RayCaster::aovImages(const ImageMap& map, const AovSelection& selection) const {
  if (selection.instance) requireExactInstances(*impl_->scene);
  impl_->rebase(impl_->originFor(map.camera(), map.size()));
  const Impl& m = *impl_;
  // Depth along the axis from the lens centre (the PRP; a real lens's entrance pupil), relative
  // to the origin the rays are kept relative to.
  const glm::dvec3 axis = -viewBasis(map.camera().view).n, eye = prpWorld(map.camera().view) - m.origin;
  return aovImagesThrough(map, selection, [&](glm::dvec2 pixel) {
    const Impl::Hit hit = m.shadeCameraRay(map, map.centreRay(pixel), 1.0);
    const double depth = std::isinf(hit.t) ? hit.t : glm::dot(hit.ray.origin + hit.t * hit.ray.direction - eye, axis);
    return AovSurface{hit.surface, depth, hit.normal, hit.albedo, hit.gltfNode};
  });
}

Image RayCaster::render(const ImageMap& map, const RaycastOptions& options,
                        const std::function<void(int, int)>& progress) const {
  impl_->rebase(impl_->originFor(map.camera(), map.size()));
  const Impl& m = *impl_;
  const auto shade = [&](const Ray& ray, const auto& rayAt, double footprintPx, glm::dvec2 pixel) {
    return m.shadeRay(ray, rayAt, footprintPx, map.camera(), pixel);
  };
  // The loop is compiled for each lens model the renderers have, so that its calls to the map are
  // direct (per ray, and per texture lookup for the ray differentials); another map goes through
  // the interface.
  const auto cast = [&](const auto& concrete) {
    return renderThroughMap(concrete, options, progress, m.origin, shade);
  };
  if (const auto* thin = dynamic_cast<const ThinLensMap*>(&map)) return cast(*thin);
  if (const auto* real = dynamic_cast<const RealLensMap*>(&map)) return cast(*real);
  return cast(map);
}

}  // namespace lenslab
