#pragma once
// One value per frame: where each pixel of the image looks into the scene. Built once from the
// camera, the image size and (for the raster) the overscan, it holds every pixel ↔ window ↔
// normalised ↔ distorted conversion and answers the renderers' two questions:
//
//   ray(pixel, lens, channel)   the ray caster: the ray leaving film point `pixel` through lens
//                               point `lens` for one colour channel (the lecture's "fire rays from
//                               every lens surface point toward this point")
//   clipFromWorld(sample, c)    the raster (ThinLensMap): the view from one aperture sample, whose
//                               true perspective image the lens pass then remaps (the tables below)
//
// Two lens models stand behind the one interface: the thin lens with its effects (ThinLensMap:
// camera/Camera.h, lens/LensEffects.h) and a traced prescription (RealLensMap: lens/LensCamera.h),
// whose real-time form for the raster is its fitted() thin lens (camera/LensFitCamera.h). A new
// lens model is a new map; the renderers' loops stay as they are. Pure C++ and GLM, no GL.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/Projection.h"
#include "camera/Ray.h"
#include "lens/AperturePattern.h"
#include "lens/CentreRays.h"
#include "lens/LensBarrel.h"
#include "lens/LensCamera.h"
#include "lens/LensEffects.h"

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace lenslab {

// The undistorted render the lens pass samples: the camera with its window widened by whole
// pixels, and that render's size. ThinLensMap::overscanned widens it by `padPx` on each side (left =
// right, top = bottom); a tile's overscan (plan/TilePlan.h) may be cut short where the full image's
// ends, so in general `padPx` is where the image's pixel (0, 0) corner sits in the render (left, top).
struct Overscan {
  Camera camera;  // lens effects still attached (the raster path needs the axial/curvature parts)
  ImageSize size;
  glm::ivec2 padPx{0, 0};
};

// For each output pixel centre, in GL row order (row 0 at the bottom), the texture coordinate in
// the overscan render of the true perspective position that channel `c` shows. One table per
// channel when there is lateral colour, else one (green's) used for all three.
struct RemapTable {
  ImageSize size;
  std::vector<std::vector<glm::vec2>> channels;  // 1 or 3 tables, size.widthPx × size.heightPx each
  bool perChannel() const { return channels.size() == 3; }
};
// How far a table is: rows done of all it has to fill (called from the calling thread).
using RowProgress = std::function<void(int rowsDone, int rows)>;

// Forward, for the raster's per-view gather (render/LensPass.h): the overscan render's texel
// centres carried through green's distortion into the output image. A view's texel t shows the
// scene at t + 0.5 + jitter; its distorted position is position + jacobian · jitter (the
// second-order term left out is below kMaxForwardLinearisationErrorPx: makeFramePlan refuses a
// lens and size where it is not). Everything in GL orientation (x right, y up, origin at the
// bottom-left corner), output positions in output pixels.
struct ForwardTable {
  ImageSize size;                   // the overscan render's
  std::vector<glm::vec4> position;  // per texel, GL row order: distorted x, y; |det J|; 0
  std::vector<glm::vec4> jacobian;  // per texel: ∂position/∂x (x, y), ∂position/∂y (z, w)
  // How far (view pixels, per axis) from the pre-image of an output pixel's centre a texel centre
  // can be and still have a jittered sample land in that pixel: the largest half-extent of an
  // output pixel's pre-image, plus one pixel for the jitter and the texel centre.
  double reachPx = 0.0;
  glm::dvec2 principalPointPx{0.0};  // the principal point in the output image, for lateral colour
};

// Channel `c` of output pixel position `pixel` (continuous, origin top left) shows the true
// perspective pixel position `pixel` here (same image grid, may lie outside it), at normalised
// position `normalised`, focused at the camera's inverse focus distance plus `inverseFocusShift`.
struct ChannelSample {
  glm::dvec2 pixel;
  glm::dvec2 normalised;
  double inverseFocusShift = 0.0;
};

// One ray a map casts for one sample of one channel.
struct CameraRay {
  Ray ray;                    // world
  double weight = 1.0;        // relative illumination (a real lens's pupil sample); 1 for a thin lens
  bool blocked = false;       // the thin lens's barrel stops it: no light, and it counts as uncovered
  glm::dvec2 pixel{0.0};      // the film point it leaves, in the map's own image (thin lens: the true
                              // perspective position; texture footprints are measured around it)
  glm::dvec2 lensPoint{0.0};  // thin lens: the lens offset (u, v; world units); real lens: the pupil sample
  int channel = 1;            // 0 red, 1 green, 2 blue
  double inverseFocusShift = 0.0;
  glm::dvec2 normalised{0.0};  // thin lens: the true perspective normalised position
};

// How a map reads its lens samples: points of the unit disk (the thin lens's aperture, shaped by
// Lens::lensOffset) or of the unit square (a real lens's box around its exit pupil).
enum class LensDomain { Disk, Square };

class ImageMap {
 public:
  virtual ~ImageMap() = default;
  ImageSize size() const { return size_; }
  // The camera the map was placed from: it names messages, and its lens centre is where the ray
  // caster keeps its geometry relative to.
  const Camera& camera() const { return camera_; }

  virtual LensDomain lensDomain() const = 0;
  // Rays per sample: 3 when the channels see differently (lateral or axial colour, dispersion).
  virtual int rayChannels() const = 0;
  // Where ray() starts for the samples of a pixel, when it solves an inverse per film point: the
  // pixel centre's solution for that channel (passed to ray() as `near`; only its solution is set,
  // not its ray). nullopt for a map that solves none.
  virtual std::optional<CameraRay> start(glm::dvec2 /*pixel*/, int /*channel*/) const { return std::nullopt; }
  // The ray from film point `pixel` (continuous, origin at the image's top-left corner) through lens
  // sample `lens` (lensDomain()) for channel 0..2 (1 when rayChannels() is 1); nullopt where the
  // sample lies outside what the lens passes (a real lens's stop and rims): it brings no light and
  // does not count toward the pixel's coverage.
  virtual std::optional<CameraRay> ray(glm::dvec2 pixel, glm::dvec2 lens, int channel,
                                       const CameraRay* near = nullptr) const = 0;
  // The same sample's ray from `offsetPx` over on the map's film (texture footprints: ray differentials).
  virtual Ray footprintRay(const CameraRay& r, glm::dvec2 offsetPx) const = 0;
  // The one ray of film point `pixel` that ground truth follows (the AOVs, core/Aovs.h): it
  // lines up with the image. nullopt where the lens passes no light from there.
  virtual std::optional<CameraRay> centreRay(glm::dvec2 pixel) const = 0;
  // What the pixel's light is multiplied by after the samples' mean (a thin lens's vignetting).
  virtual double gainAt(glm::dvec2 /*pixel*/) const { return 1.0; }

 protected:
  ImageMap(Camera camera, ImageSize size) : camera_(std::move(camera)), size_(size) {}
  ImageMap(const ImageMap&) = default;
  ImageMap& operator=(const ImageMap&) = default;

  Camera camera_;
  ImageSize size_;
};

// The thin lens (the lecture's camera) with its lens effects: distortion and lateral colour move
// where each film point looks (an inverse solved per ray, exactly), axial colour and field
// curvature where it is focused, vignetting scales its light, the barrel stops rays.
class ThinLensMap final : public ImageMap {
 public:
  // Rays and conversions; its render is the image itself until overscanned().
  ThinLensMap(const Camera& camera, ImageSize size);
  // A plan's map: the render `overscan` given (the frame's, or a tile's part of it).
  ThinLensMap(const Camera& camera, ImageSize size, Overscan overscan);
  // The map of `camera`'s true perspective image: its lens effects left out, so that each pixel is
  // a pinhole view's own (the barrel, which stops rays instead of moving them, still stops them).
  // Where a depth lookup at an already undistorted pixel casts its ray (camera/FocusOnPixel.h).
  static ThinLensMap truePerspective(const Camera& camera, ImageSize size);
  // This map with the render widened for the lens pass: the output's border maps to the border of
  // the region it shows (validateLensEffects refuses folds), so the border's true positions bound
  // everything the lens pass samples, plus 2 pixels for its footprint. No limit on the size here:
  // a render larger than one GL target is made in tiles (plan/TilePlan.h).
  ThinLensMap overscanned() const;
  // This map with the render widened by `padPx` whole pixels on each side (left = right, top =
  // bottom): the lens pass's overscan, or the cell filter's margin (its images reach in from outside).
  ThinLensMap paddedBy(glm::ivec2 padPx) const;

  // Conversions on the output image (continuous pixels, origin top left, +y down).
  glm::dvec2 windowFromPixel(glm::dvec2 pixel) const;
  glm::dvec2 pixelFromWindow(glm::dvec2 uv) const;
  glm::dvec2 normalisedFromPixel(glm::dvec2 pixel) const;  // perspective only
  glm::dvec2 pixelFromNormalised(glm::dvec2 normalised) const;
  // Where world point `world` shows on the output image, green's (through the lens's distortion):
  // the lecture's projection onto the view plane from the PRP, then distorted. nullopt for a point
  // not in front of the lens centre (perspective only).
  std::optional<glm::dvec2> pixelOfPoint(const glm::dvec3& world) const;
  // Exact, per point: the true perspective sample channel `c` of output position `pixel` shows,
  // Newton started from `guess` (a true normalised position; the pixel's own when not given).
  ChannelSample undistorted(Channel c, glm::dvec2 pixel, std::optional<glm::dvec2> guess = std::nullopt) const;
  // Green's true perspective position of output pixel `pixel` in the render's pixels (overscan
  // included): where the raster's undistorted views show what that pixel shows.
  glm::dvec2 renderPixelFromOutput(glm::dvec2 pixel) const;
  // Where green's distortion carries render pixel position `renderPixel` (image orientation) in
  // the output image: the forward table's map.
  glm::dvec2 outputFromRenderPixel(glm::dvec2 renderPixel) const;

  // The raster's render: the overscan's camera and size, and the view from one aperture sample
  // (its lens point and sub-pixel jitter) focused for channel `c` (axial colour; green's focus is
  // the camera's own), as GL clip coordinates. Points land on the render's pixels; the lens pass
  // (the tables below) carries them to the output's.
  const Overscan& overscan() const { return overscan_; }
  bool remaps() const { return camera_.lens.effects.needsRemap(); }
  glm::dmat4 clipFromWorld(const LensSample& s, Channel c) const;
  // Normalised image coordinates of the render's GL pixel corner (0, 0), and their step per pixel:
  // the field-curvature warp's and the barrel mask's coordinates.
  glm::dvec2 normalisedAtRenderCorner() const;
  glm::dvec2 normalisedPerRenderPixel() const;

  // The ray caster's questions (ImageMap).
  LensDomain lensDomain() const override { return LensDomain::Disk; }
  int rayChannels() const override { return rayChannels_; }
  std::optional<CameraRay> start(glm::dvec2 pixel, int channel) const override;
  std::optional<CameraRay> ray(glm::dvec2 pixel, glm::dvec2 lens, int channel,
                               const CameraRay* near = nullptr) const override;
  // Inline: the ray caster's loop, compiled for this map (RayCaster::render), calls it for every
  // texture lookup's ray differentials.
  Ray footprintRay(const CameraRay& r, glm::dvec2 offsetPx) const override {
    return lensRay(rayCamera_, r.lensPoint, r.pixel + offsetPx, size_, r.inverseFocusShift);
  }
  // Green's ray from the lens centre, through the inverse lens model. The barrel dims the light
  // it does not hide the surface behind it, so the ray is never blocked.
  std::optional<CameraRay> centreRay(glm::dvec2 pixel) const override;
  double gainAt(glm::dvec2 pixel) const override;

  // The lens pass's tables (camera/LensMap.cpp), filled on every core: one inverse table for each
  // of remappedChannels(camera().effects) (camera/LensMap.h).
  RemapTable remapTable(const RowProgress& progress = {}) const;
  // Rows [firstRow, lastRow) (GL order) of channel `c`'s table into `out` (size().widthPx per row):
  // for a caller that uploads a table a band at a time instead of holding it whole.
  void fillRemapRows(Channel c, int firstRow, int lastRow, glm::vec2* out) const;
  ForwardTable forwardTable(const RowProgress& progress = {}) const;
  // The forward table a band at a time: rows [firstRow, lastRow) of the render into `position` and
  // `jacobian` (overscan().size.widthPx per row). Returns the band's largest half-extent of an
  // output pixel's pre-image (render pixels), for forwardReachPx over all bands.
  double fillForwardRows(int firstRow, int lastRow, glm::vec4* position, glm::vec4* jacobian) const;
  double forwardReachPx(double largestHalfExtentPx) const;
  glm::dvec2 forwardPrincipalPointPx() const;
  // How far, in output pixels, the raster's samples can land from where the lens puts them
  // (ForwardTable): each rendered pixel carries its samples by the lens's linear map over that
  // pixel (central differences), whose error is the map's second-order term over half a pixel —
  // the largest over the image (green's distortion, scaled by the lateral colour's magnification).
  // Proportional to the pixel pitch: a wider image halves it with each doubling.
  double forwardLinearisationErrorPx() const;
  // Throws InputError (naming the camera's source, the coefficients, the error, the limit and the
  // width that would meet it) when forwardLinearisationErrorPx exceeds the limit.
  void validateForwardLinearisation() const;

 private:
  // Green's (or channel `c`'s) true perspective normalised position of the distorted one; throws
  // InputError where the lens's branch has none (it folds before it).
  glm::dvec2 undistortNormalised(Channel c, glm::dvec2 distorted, glm::dvec2 guess) const;

  Overscan overscan_;
  Camera rayCamera_;        // the camera the rays are built with: its lens effects applied by the map, per ray
  bool movesRays_ = false;  // effects besides vignetting: each ray goes through the inverse lens model
  int rayChannels_ = 1;
};

// Inline, as footprintRay: the ray caster's loop calls it for every ray.
inline std::optional<CameraRay> ThinLensMap::ray(glm::dvec2 pixel, glm::dvec2 lens, int channel,
                                                 const CameraRay* near) const {
  std::optional<CameraRay> out(std::in_place);  // built in place: this runs for every ray
  CameraRay& r = *out;
  r.channel = channel;
  r.lensPoint = camera_.lens.lensOffset(lens);
  r.pixel = pixel;
  if (movesRays_) {
    // Exactly, per ray: the true perspective position that the inverse lens model gives for this
    // point of the distorted image, focused on that channel's (and that radius's) plane of focus.
    const ChannelSample s =
        undistorted(static_cast<Channel>(channel), pixel, near ? std::optional(near->normalised) : std::nullopt);
    r.pixel = s.pixel;
    r.normalised = s.normalised;
    r.inverseFocusShift = s.inverseFocusShift;
  }
  r.ray = lensRay(rayCamera_, r.lensPoint, r.pixel, size_, r.inverseFocusShift);
  // The barrel's opening (cat's-eye vignetting). The lecture's thin lens deflects the ray from
  // aperture point p toward the point of the plane of focus seen in the undistorted direction n;
  // that ray is the one the barrel may stop, at p·(1 − L/z_f) + L·n. Distortion and lateral colour
  // only move where on the film that ray lands, so the test takes n of the undistorted position,
  // never the distorted film point, and z_f with the channel's and the curvature's shift.
  if (rayCamera_.lens.hasBarrel()) {
    const glm::dvec2 w = lenslab::windowFromPixel(rayCamera_.view.window, r.pixel, size_.widthPx, size_.heightPx);
    const glm::dvec2 normalised = (w - glm::dvec2(rayCamera_.view.prp)) / rayCamera_.view.prp.z;
    r.blocked = !throughBarrel(rayCamera_.lens.barrel, r.lensPoint, normalised,
                               rayCamera_.inverseFocusDistance() + r.inverseFocusShift);
  }
  return out;
}

// A real lens: the traced prescription (lens/LensCamera), placed from `placed`; for each film point
// and each pupil sample the ray leaves the lens into the scene, weighted by its relative
// illumination. Its raster form is the thin lens fitted to it (camera/LensFitCamera), fitted().
class RealLensMap final : public ImageMap {
 public:
  RealLensMap(LensCamera lens, const Camera& placed, ImageSize size, std::optional<Camera> fittedCamera = std::nullopt);

  const LensCamera& lens() const { return lens_; }
  bool hasFitted() const { return fitted_ != nullptr; }
  // The fitted real-time lens's map (throws std::logic_error when the map was built without one).
  const ThinLensMap& fitted() const;

  LensDomain lensDomain() const override { return LensDomain::Square; }
  int rayChannels() const override { return lens_.dispersion() ? 3 : 1; }
  std::optional<CameraRay> ray(glm::dvec2 pixel, glm::dvec2 lens, int channel,
                               const CameraRay* near = nullptr) const override;
  Ray footprintRay(const CameraRay& r, glm::dvec2 offsetPx) const override;
  // Green's bundle's mean line (lens/CentreRays.h), the centre of the pixel's blur; its lens
  // point is the pupil box's centre (for the texture footprint). Traced on first use.
  std::optional<CameraRay> centreRay(glm::dvec2 pixel) const override;

 private:
  LensCamera lens_;
  std::shared_ptr<const ThinLensMap> fitted_;
  // Built once, on the first centreRay, by whichever thread asks first; copies share it.
  struct LazyCentreRays {
    std::once_flag once;
    std::unique_ptr<CentreRays> rays;
  };
  std::shared_ptr<LazyCentreRays> centreRays_ = std::make_shared<LazyCentreRays>();
};

}  // namespace lenslab
