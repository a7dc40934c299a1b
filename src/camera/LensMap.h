#pragma once
// The lens effects (lens/LensEffects.h) applied to a camera's image: which pixel of the true
// perspective image each output pixel shows, per colour channel.
//
// The raster path renders the true perspective image (with depth of field) over a window a little
// larger than the camera's (overscan: same centre, same pixel pitch, whole pixels added on each
// side) and carries each view's samples forward to where the lens puts them (ForwardTable), or
// remaps a single view through a table of the inverse positions (RemapTable). The ray caster casts
// each output sample's ray through the same inverse mapping, exactly, per sample.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "lens/LensEffects.h"

#include <glm/glm.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Throws InputError naming `where` when the camera's lens effects cannot be rendered: effects on a
// parallel projection, non-finite or out-of-range values, a channel's or the curved surface's plane
// of focus no nearer than `focalLength` (world units; without one, the aperture radius), or a
// distortion that folds over inside the image (see findFoldOver); the message says which field,
// what it is and what to change.
void validateLensEffects(const Camera& camera, const std::string& where, std::optional<double> focalLength = std::nullopt);

// The normalised-coordinate rectangle covered by the camera's window.
struct NormalisedRect {
  glm::dvec2 min, max;
  double cornerRadius() const;  // distance of the farthest corner from the principal point
};
NormalisedRect normalisedWindow(const ViewSpec& view);

// The inverse focus shifts over which a camera's circle of confusion is largest: each colour's
// plane of focus (axial colour), flat and at the window's farthest corner (field curvature).
// A parallel projection has no corners to curve toward (its circle ignores the shift).
std::vector<double> extremeFocusShifts(const Camera& camera);

// The undistorted render the post pass samples: the camera with its window widened by whole
// pixels, and that render's size. overscanFor widens it by `padPx` on each side (left = right,
// top = bottom); a tile's overscan (plan/TilePlan.h) may be cut short where the full image's ends,
// so in general `padPx` is where the image's pixel (0, 0) corner sits in the render (left, top).
struct Overscan {
  Camera camera;     // lens effects still attached (the raster path needs the axial/curvature parts)
  ImageSize size;
  glm::ivec2 padPx{0, 0};
};
Overscan overscanFor(const Camera& camera, ImageSize size);

// How far, in output pixels, the raster's samples can land from where the lens puts them at `size`
// (ForwardTable): each rendered pixel carries its samples by the lens's linear map over that pixel
// (central differences), whose error is the map's second-order term over half a pixel — the
// largest over the image (green's distortion, scaled by the lateral colour's magnification).
// Proportional to the pixel pitch: a wider image halves it with each doubling.
double forwardLinearisationErrorPx(const Camera& camera, ImageSize size);

// Beyond this the samples of a rendered pixel land in the wrong output pixel, and the raster
// converges to a wrong image whatever the number of views (k1 = 1e6 on `rows` at 63 px: 196 px,
// a patchwork of a few samples where the ray caster shows a magnified floor). Measured on `rows` at 63 px, raster against a 1024-spp ray cast:
// 0.4 px (k1 = 100) reaches 36.7 dB at 2048 views and still rises; 2 px (k1 = 1000) stays at 23.6 dB.
constexpr double kMaxForwardLinearisationErrorPx = 0.5;

// Throws InputError (naming the camera's source, the coefficients, the error, the limit and the
// width that would meet it) when forwardLinearisationErrorPx exceeds the limit at `size`.
void validateForwardLinearisation(const Camera& camera, ImageSize size);

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
RemapTable makeRemapTable(const Camera& camera, ImageSize size, const Overscan& overscan, const RowProgress& progress = {});
// The channels with a table of their own: red, green and blue with lateral colour, else green.
std::vector<Channel> remappedChannels(const LensEffects& effects);
// Rows [firstRow, lastRow) (GL order) of channel `c`'s table into `out` (size.widthPx per row),
// on every core: for a caller that uploads a table a band at a time instead of holding it whole
// (a table for a 4096-pixel tile is hundreds of MB). The same values as makeRemapTable's rows.
void fillRemapRows(const Camera& camera, ImageSize size, const Overscan& overscan, Channel c, int firstRow, int lastRow,
                   glm::vec2* out);

// Forward, for the raster's per-view gather (render/LensPass.h): the overscan render's texel
// centres carried through green's distortion into the output image. A view's texel t shows the
// scene at t + 0.5 + jitter; its distorted position is position + jacobian · jitter (the
// second-order term left out is below kMaxForwardLinearisationErrorPx: makeFramePlan refuses a
// lens and size where it is not). Everything in GL
// orientation (x right, y up, origin at the bottom-left corner), output positions in output pixels.
struct ForwardTable {
  ImageSize size;                    // the overscan render's
  std::vector<glm::vec4> position;   // per texel, GL row order: distorted x, y; |det J|; 0
  std::vector<glm::vec4> jacobian;   // per texel: ∂position/∂x (x, y), ∂position/∂y (z, w)
  // How far (view pixels, per axis) from the pre-image of an output pixel's centre a texel centre
  // can be and still have a jittered sample land in that pixel: the largest half-extent of an
  // output pixel's pre-image, plus one pixel for the jitter and the texel centre.
  double reachPx = 0.0;
  glm::dvec2 principalPointPx{0.0};  // the principal point in the output image, for lateral colour
};
ForwardTable makeForwardTable(const Camera& camera, ImageSize size, const Overscan& overscan, const RowProgress& progress = {});
// The forward table a band at a time (as fillRemapRows): rows [firstRow, lastRow) of the overscan
// render into `position` and `jacobian` (overscan.size.widthPx per row). Returns the band's largest
// half-extent of an output pixel's pre-image (view pixels), for forwardReachPx over all bands.
double fillForwardRows(const Camera& camera, ImageSize size, const Overscan& overscan, int firstRow, int lastRow,
                       glm::vec4* position, glm::vec4* jacobian);
// ForwardTable::reachPx from the largest half-extent over all rows, and its principal point.
double forwardReachPx(const Camera& camera, double largestHalfExtentPx);
glm::dvec2 forwardPrincipalPointPx(const Camera& camera, ImageSize size);

// Exact, for the ray caster: channel `c` of output pixel position `pixel` (continuous, origin top
// left) shows the true perspective pixel position returned (same image grid, may lie outside it),
// focused at the camera's inverse focus distance plus `inverseFocusShift`. `guess` is a true
// normalised position to start Newton from (the pixel centre's); `normalised` receives the result.
struct ChannelSample {
  glm::dvec2 pixel;
  glm::dvec2 normalised;
  double inverseFocusShift = 0.0;
};
ChannelSample undistortedSample(const Camera& camera, Channel c, glm::dvec2 pixel, ImageSize size, glm::dvec2 guess);
// The same, with Newton started from the pixel's own (distorted) position.
ChannelSample undistortedSample(const Camera& camera, Channel c, glm::dvec2 pixel, ImageSize size);

}  // namespace lenslab
