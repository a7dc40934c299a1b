#pragma once
// The CPU reference: the lecture's ray casting, "for each pixel, ray R from PRP toward
// VRP + u·udir + v·vdir; P = Intersect(R, World); Image[u, v] = Color(P)", through the thin lens
// ("rays from every lens surface point toward the in-focus point, averaged"). It asks the same
// image map as the rasterizer for its rays (camera/ImageMap.h), and uses the same Scene and the
// same shading, so any difference between the two images is the rasterizer's method error.
// Surfaces of alphaMode BLEND are composited along each ray, front to back, exactly per ray
// (shadeAlong; docs/materials.md). Embree finds the hits (raycast/EmbreeScene.h); one loop casts
// every lens's rays, TBB spreading rows over the cores (raycast/RenderLoop.h).
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/ImageSize.h"
#include "core/Aovs.h"
#include "core/Image.h"
#include "lens/LensCamera.h"
#include "scene/Scene.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lenslab {

struct RaycastOptions {
  // Stratified pixel × lens samples (Shirley–Chiu concentric on the lens). Each sample's texture
  // lookups are filtered over its own stratum (1/√spp of a pixel), so the image converges to the
  // pixel integral of the unfiltered (level-0) texture as spp grows.
  int samplesPerPixel = 64;
  std::uint32_t seed = 1;
};

class RayCaster {
 public:
  explicit RayCaster(const Scene& scene);  // builds the Embree scene; `scene` must outlive it
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // `progress(rowsDone, rows)` is called from the calling thread between bands of rows.
  Image render(const Camera& camera, ImageSize size, const RaycastOptions& options,
               const std::function<void(int, int)>& progress = {}) const {
    return render(ThinLensMap(camera, size), options, progress);
  }

  // The one ray-casting loop, for every lens (raycast/RenderLoop.h): each pixel's stratified
  // samples (pixel position × lens point, in the map's lens domain), each channel's ray asked of the
  // map, shaded, weighted by the ray's weight, averaged, times the map's gain at the pixel. The
  // thin-lens and real-lens overloads build their map and call it.
  Image render(const ImageMap& map, const RaycastOptions& options,
               const std::function<void(int, int)>& progress = {}) const;

  // The reference image through a real lens (lens/LensCamera, `raycast --lens`): each sample is a
  // film point in the pixel and a point of the exit pupil seen from it, traced through every
  // surface of the prescription (per channel when it has Abbe numbers) and weighted by its
  // projected solid angle, so the corners darken as the lens's relative illumination says.
  // `camera` is the one the lens camera was placed from: it sets where the scene's geometry is
  // kept relative to, and names messages.
  Image render(const LensCamera& lens, const Camera& camera, ImageSize size, const RaycastOptions& options,
               const std::function<void(int, int)>& progress = {}) const {
    return render(RealLensMap(lens, camera, size), options, progress);
  }

  // The shaded colour seen along one of the map's rays: from continuous film position `pixel`
  // through lens sample `lens` (in the map's lensDomain(); the unit disk's centre is a thin lens's
  // centre) for `channel` (1 green; 0..2 where the map's rayChannels() is 3), linear RGB; the
  // background where nothing is hit, black where the lens stops the ray. Textures are filtered
  // over `footprintPx` pixels around the ray (1: a whole pixel, as one GL view would).
  glm::vec3 trace(const ImageMap& map, glm::dvec2 pixel, glm::dvec2 lens, int channel = 1,
                  double footprintPx = 1.0) const;

  // Depth (world units from the PRP along −n) of the first visible surface under pixel centre
  // `pixel` of a pinhole view of `camera` (its lens effects left out: ThinLensMap::truePerspective)
  // seen from the lens centre; +infinity where nothing is hit. For --focus-at
  // (camera/FocusOnPixel.h's DepthAtPixel).
  double depthAt(const Camera& camera, glm::dvec2 pixel, ImageSize size) const;

  // The depth AOV (`capture --aov depth`): for each pixel centre, the distance along the optical
  // axis (−n) from the lens centre (the PRP) to the first surface seen through it, in world units,
  // +infinity where nothing is hit (OpenEXR's convention for Z). With lens effects the pixel is
  // first taken back through the inverse lens model (green's), so depth lines up with the image.
  // One ray per pixel: depth is not averaged over the pixel or the aperture. Rows from the top.
  std::vector<float> depthImage(const Camera& camera, ImageSize size) const;

  // The selected AOVs (core/Aovs.h) of the same ray per pixel as depthImage: the first surface
  // seen through each pixel centre from the lens centre. A surface of alphaMode BLEND counts when
  // its alpha is at least 0.5 (as Blender Cycles' pass alpha threshold); a fainter one is seen
  // through, to what lies behind it. depthAt and depthImage see the same surface. The normal is the one that surface is
  // shaded with, in camera space (u, v, n: right, up, toward the viewer); the albedo its base
  // colour (factor × texture over one pixel × vertex colour, linear); the instance its glTF node.
  AovImages aovImages(const Camera& camera, ImageSize size, const AovSelection& selection) const;
  // The same through any lens model: the first surface along each pixel centre's
  // ImageMap::centreRay (a real lens's: the mean line of the bundle, lens/CentreRays.h), depth
  // measured along the axis from the map's lens centre.
  AovImages aovImages(const ImageMap& map, const AovSelection& selection) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lenslab
