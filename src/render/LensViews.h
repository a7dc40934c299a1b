#pragma once
// The raster's views of one frame, the lecture's accumulation buffer: each aperture sample is the
// scene seen from one point of the lens with a sub-pixel jitter, once per colour channel when each
// colour has its own plane of focus (axial colour). Everything a view needs is asked of the
// frame's image map (camera/ImageMap.h), built once by Renderer::begin: its clipFromWorld, and
// what the accumulator adds it with (its channels, the field-curvature shift, the jitter, the
// barrel's view of its aperture point, the normalised coordinates of its pixels).
#include "camera/ImageMap.h"
#include "lens/AperturePattern.h"
#include "plan/FramePlan.h"
#include "render/Accumulator.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace lenslab {

class LensViews {
 public:
  LensViews(ThinLensMap map, const FramePlan& plan);

  const ThinLensMap& map() const { return map_; }

  // One view of a sample: the colours it adds, and the focus they are drawn with.
  struct ChannelView {
    glm::vec3 mask{1.0f};
    Channel channel = Channel::Green;  // one view for all is focused as green: the camera's own focus
  };
  const std::vector<ChannelView>& channelViews() const { return channels_; }
  glm::dmat4 clipFromWorld(const LensSample& s, Channel c) const { return map_.clipFromWorld(s, c); }

  // Field curvature: the view's shift at r = 1, δ·d·κ, in render pixels (Accumulator.h).
  glm::vec2 curvatureShiftPx(const LensSample& s) const;
  // The sub-pixel offset in render pixels, GL orientation, for the lens gather.
  static glm::vec2 jitterPx(const LensSample& s) {
    return {static_cast<float>(s.pixel.x), static_cast<float>(-s.pixel.y)};
  }
  // Where the barrel sees this view's aperture point, p·(1 − L/z_f) over the opening's radius, z_f
  // channel `c`'s focus; 0 without a barrel.
  glm::vec2 barrelLens(const LensSample& s, Channel c) const;

  // The cell filter's inputs for the view of sample `s` in aperture cell `cell`, channel `c`: its
  // spread (camera/CellSpread.h) and how far a neighbour's image can reach: over the frame's depths,
  // and no farther than the cell's share of the largest circle of confusion in view (the pre-pass's,
  // when it ran), and at most kCellFilterMaxReachPx (lens/ApertureCells.h).
  Accumulator::CellView cellView(const LensSample& s, const ApertureCell& cell, Channel c) const;

  // The field-curvature warp's coordinates for the views (Accumulator::Curvature), if the plan has one.
  std::optional<Accumulator::Curvature> curvatureWarp() const;
  // The barrel's per-pixel mask for the views (Accumulator::Barrel), if the camera has a barrel.
  std::optional<Accumulator::Barrel> barrelMask() const;

 private:
  // Normalised image coordinates of the views' GL pixel corner (0, 0) and their step per pixel
  // (the mapping both the field-curvature warp and the barrel's mask take).
  Accumulator::Curvature normalisedPixels() const;
  const Camera& rendered() const { return map_.overscan().camera; }

  ThinLensMap map_;
  bool fieldCurvature_ = false;
  double depthMin_ = 0.0, depthMax_ = 0.0;  // the plan's depth range of the scene in view
  double cocMaxPx_ = 0.0;                   // and its largest circle of confusion (the pre-pass's, when it ran)
  std::vector<ChannelView> channels_;
};

}  // namespace lenslab
