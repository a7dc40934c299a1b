#pragma once
// Thin-lens depth of field by accumulation: the image is the mean of the aperture views.
//
// Plain views are added by the scene pass itself (ScenePass's added views: a depth pass, then a
// colour pass that blends where depth is EQUAL) into a float partial sum: no layer of its own.
// The partial sum holds weight · (colour − background) per view, so that a pixel no surface
// covers costs a view nothing; every 64 views one full-screen pass adds it and their
// weight · background to the sum (two levels: a sum of 65536 views stays within 1e-4).
//
// Views that are read whole when summed (the field-curvature warp, the lens gather) are drawn
// into the layers of an array texture (one framebuffer per layer, one shared depth buffer), and a
// batch of them is added into the sum by one full-screen pass. start / nextView / resolve let the
// samples spread over frames (the interactive demo converges progressively).
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/Object.h"
#include "lens/ApertureCells.h"
#include "plan/TileBudget.h"
#include "render/VignetteGain.h"

#include <glm/glm.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

namespace lenslab {

class Accumulator {
 public:
  Accumulator();  // builds the programs (needs a current context)

  // Field curvature, applied when views are summed. A view from lens offset δ focused at inverse
  // distance φ puts a point of depth Z at window position d·X/Z + δ·d·(φ − 1/Z), so focusing pixel
  // x at φ + κ·r(x)² instead of φ shows what the flat-focused view has at x − δ·d·κ·r(x)²: a
  // smooth warp of each view that does not depend on depth. Summing the views through that warp
  // (Catmull–Rom) gives the curved focal surface exactly, up to the resampling.
  struct Curvature {
    glm::vec2 normalisedAtOrigin;  // normalised image coordinates of GL pixel corner (0, 0)
    glm::vec2 normalisedPerPixel;  // and their step per pixel (x right, y up)
  };

  // Distortion and lateral colour applied to each view as it is summed (gather_lens.frag): the
  // sum is then at the output's size, the views at the overscan's. Made by LensPass.
  struct LensGather {
    GLuint forwardPosition = 0;  // RGBA32F at the views' size (camera/LensMap.h ForwardTable)
    GLuint forwardJacobian = 0;
    GLuint inverse[3] = {
        0, 0, 0};  // RG32F remap tables at the output size: red, green, blue (all green's without lateral colour)
    bool lateral = false;
    int outWidthPx = 0;
    int outHeightPx = 0;
    float reachPx = 0.0f;
    glm::vec2 principalPointPx{0.0f};
    glm::vec2 lateralScale{1.0f};  // 1 + lateral, red and blue
  };

  // Cat's-eye vignetting (lens/LensBarrel.h), applied per pixel as the views are summed: a view
  // adds nothing (background included) where the barrel's opening hides its aperture point from
  // the pixel's direction n. The mapping to n as Curvature's; `reach` = barrel distance / radius.
  // Views are then layers (an added view has no per-pixel weight). With the lens gather, each
  // view sample is masked at its own undistorted position (the views' grid: the overscan's), and
  // a stopped sample still counts in the pixel's weight, as a ray that brings no light.
  struct Barrel {
    glm::vec2 normalisedAtOrigin;
    glm::vec2 normalisedPerPixel;
    float reach = 0.0f;
  };
  // The cell filter (cell_filter.frag): each view, drawn into a layer, is spread over its cell's
  // image at each pixel's depth as it is added, one view at a time (the views share one depth
  // buffer, which the filter reads). Made by render/LensViews per view.
  struct CellView {
    glm::mat2 spreadAtInfinity{0.0f};       // image pixels (GL orientation) per unit of aperture point
    glm::mat2 spreadPerInverseDepth{0.0f};  // plus this times 1/Z
    glm::vec2 inverseDepthFromNdc{0.0f};    // 1/Z = x·z_ndc + y
    glm::vec2 lensPoint{0.0f};              // the view's aperture point (after the shape's map)
    ApertureCell cell;                      // on the unit disk, before the shape's map
    ApertureShape shape;
    // The displacements x − y (pixels, per axis) from a neighbour y to the pixels x its image can cover.
    glm::ivec2 displacementMinPx{0}, displacementMaxPx{0};
    float depthReference = 1.0f;  // a depth in view (world units), the scale of the fill's weights
  };
  // Before start(); the views are then `marginPx` wider than the sum on each side.
  void setCellFilter(bool on, glm::ivec2 marginPx = glm::ivec2(0)) {
    cellFilter_ = on;
    cellMarginPx_ = on ? marginPx : glm::ivec2(0);
  }
  bool cellFilter() const { return cellFilter_; }
  // Views from the next one on go into layers even where they could be added straight into the
  // sum: an added view draws the scene twice (depth, then colour), so where vertices cost more
  // than pixels (a big scene at a small size) layers are cheaper. Tests and benchmarks compare too.
  // Renderer sets it for every view of a scene with alphaMode BLEND (ScenePass.h says why).
  void setLayered(bool layered) { forceLayers_ = layered; }
  // Whether layers cost less than added views for a scene pass of `triangles` into `pixels`: an
  // added view pays a second pass over the geometry, a layered one a write and a read of the
  // layer. On llvmpipe (lenslab_ratios --breakdown, layered ÷ added frames at 1280×720: 74
  // triangles 1.44 ÷ 0.87, 107 k 1.43 ÷ 1.47, 305 k 1.06 ÷ 1.43) they cross near 0.1 triangles a pixel.
  static bool layersAreCheaper(double triangles, double pixels) {
    return triangles > kTrianglesPerPixelForLayers * pixels;
  }
  static constexpr double kTrianglesPerPixelForLayers = 0.1;
  // Each view's weight is scaled by 1 / (the views expected, rounded up to a power of two), so the
  // sum holds about the mean, not N times it: a radiance near a float's largest (3.4e38) does not
  // overflow as the views are summed. A power of two scales exactly, and the resolve divides by
  // the scaled weights, so the image is the same bit for bit. Before start(); 1 view: no scale.
  void setExpectedViews(int views) {
    viewScale_ =
        views > 1 ? std::ldexp(1.0f, -static_cast<int>(std::ceil(std::log2(static_cast<double>(views))))) : 1.0f;
  }
  float viewScale() const { return viewScale_; }
  // Clears the sum. Views are widthPx × heightPx; the sum too, unless `lens` is given.
  void start(int widthPx, int heightPx, const Curvature* curvature = nullptr, const LensGather* lens = nullptr,
             const Barrel* barrel = nullptr);
  // Where and how to draw the next view: into `target`, replacing it (a layer), or, when
  // `addWeight` is set, added into the sum with that weight (ScenePass::draw's addWeight). It
  // counts as added once drawn.
  struct View {
    gl::DrawTarget target;
    std::optional<glm::vec4> addWeight;
  };
  // The next view. Adds the previous batch to the sum first when the batch is full. `background`
  // is the scene's (what a view shows where no surface is). `channels` says which colour channels
  // the view contributes (axial chromatic aberration draws one view per channel); resolve divides
  // each channel by the number of views that contributed to it.
  // `curvatureShiftPx`: δ·d·κ of this view in pixels (GL orientation), used with start's Curvature.
  // `jitterPx`: the view's sub-pixel offset (GL orientation), used with start's LensGather.
  // `barrelLens`: with start's Barrel, the view's aperture point seen in the opening's plane over
  // the opening's radius, p·(1 − distance/z_f) / radius.
  // `cell`: the view's cell, with setCellFilter.
  View nextView(glm::vec3 background, glm::vec3 channels = glm::vec3(1.0f),
                glm::vec2 curvatureShiftPx = glm::vec2(0.0f), glm::vec2 jitterPx = glm::vec2(0.0f),
                glm::vec2 barrelLens = glm::vec2(0.0f), const CellView* cell = nullptr);
  // Views added from now on reach only these rectangles of the sum (nullptr: all of it); the views
  // pending so far are added first, with the region they were drawn for. Per-tile budgets.
  void setRegion(const std::vector<PixelBox>* boxes);
  // The sum itself, for a caller that divides per tile (render/Renderer's two-stream resolve):
  // RGBA32F; with perPixelWeight(), the per-pixel weights beside it (else 0). Adds pending views first.
  GLuint sumTexture();
  GLuint weightTexture();
  // Whether each pixel sums its own weights: the lens gather's samples land unevenly, and where
  // the barrel stops a view, alpha's weight leaves it out (coverage is over the rays that pass).
  bool perPixelWeight() const { return lens_.has_value() || barrel_.has_value(); }
  int count() const { return count_; }
  // Views per batch: layers (kMaxBatch before any), or views whose background is added by one pass.
  int batchSize() const {
    return addsViews()             ? kAddedBatch
           : cellFilter_           ? 1
           : framebuffers_.empty() ? kMaxBatch
                                   : static_cast<int>(framebuffers_.size());
  }
  // Whether the next view is added straight into the sum (no field-curvature warp, no lens
  // gather, not setLayered).
  bool addsViews() const { return mayAdd_ && !forceLayers_ && !cellFilter_; }
  // A model of what a view costs as the accumulator draws it now, for benchmarks to print: scene
  // passes per view (an added view draws the scene twice: depth, then colour), full-screen passes
  // per view, and the bytes per pixel its own work moves per view apart from the scene's fragments
  // (clears, layer reads, the sum's read-modify-write; llvmpipe keeps depth-stencil in 8 bytes).
  // A bare scene pass clears 20 bytes per pixel (RGBA32F and depth).
  struct ViewCost {
    double scenePasses = 0.0;
    double fullScreenPasses = 0.0;
    double bytesPerPixel = 0.0;
  };
  ViewCost viewCost() const;
  // The mean so far, into `out` (the sum's size); times the vignetting gain when given one (the
  // resolve is then the frame's last pass, and no pass of its own is needed for it).
  void resolve(const gl::RenderTarget& out, const VignetteGain* vignetting = nullptr);

 private:
  void flush();        // adds the pending views to the sum
  void flushLayers();  // the pending layers, summed into the sum
  void filterView();   // the cell filter: the pending view, spread over its cell, into the sum
  // A full-screen pass of `program` over the view layers (texture unit 0), within setRegion's rectangles.
  void drawViewsInRegion(GLuint program) const;
  void flushBackground();  // added views: their partial sum and weight · background, into the sum
  void allocateAddTarget();
  void resetDepthStencil(float depth, int stencil, bool inRegionOnly);
  void allocateLayers(int widthPx, int heightPx);
  static int layersFor(int widthPx, int heightPx);  // as many as kBatchMemoryBytes holds, 1 to kMaxBatch

  static constexpr int kAddedBatch = 64;  // added views between background passes (any number would do)
  static constexpr int kMaxBatch = 8;     // layers at most (the accumulate shaders' arrays)

  gl::Program accumulate_;
  gl::Program accumulateCurved_;     // the field-curvature variant, built on first use
  gl::Program accumulateBarrel_[2];  // with the barrel: [field curvature], built on first use
  gl::Program gatherLens_[8];        // the lens gather: [gatherVariant()], built on first use
  // The lens gather's variant for start's effects: barrel · 4 + field curvature · 2 + lateral colour.
  int gatherVariant() const { return (barrel_ ? 4 : 0) + (curvature_ ? 2 : 0) + (lens_ && lens_->lateral ? 1 : 0); }
  // The resolve's variants, built on first use: [plain, the lens gather's per-pixel weights
  // (PER_PIXEL_WEIGHT), the cell filter's fill (CELL_FILL)][VIGNETTING].
  gl::Program resolvePrograms_[3][2];
  gl::Program cellFilterProgram_;  // the cell filter, built on first use
  gl::Program addBatch_;           // added views: a batch's partial sum and background into the sum
  gl::FullScreenPass fullScreen_;
  std::unique_ptr<gl::RenderTarget> sum_;
  std::unique_ptr<gl::RenderTarget> weight_;  // per-pixel weights: the lens gather's, the cell filter's coverage
  gl::Framebuffer gatherFramebuffer_;         // sum_ and weight_ as two colour attachments
  std::unique_ptr<gl::RenderTarget> behind_;  // the cell filter's farthest surfaces (cell_filter.frag)
  std::unique_ptr<gl::RenderTarget> holes_;   // and the coverage its views miss behind edges
  gl::Framebuffer cellFramebuffer_;           // sum_, weight_ and behind_
  std::optional<LensGather> lens_;
  gl::TextureArray views_;  // RGBA32F, one layer per view of a batch
  gl::Texture depth_;       // shared by the views (each clears it)
  std::vector<gl::Framebuffer> framebuffers_;
  // Added views: a partial sum with a depth-stencil of its own (depth far and stencil 0 where the
  // next view may add, stencil 1 outside the region).
  bool mayAdd_ = false;  // no field curvature, no lens gather
  bool forceLayers_ = false;
  bool cellFilter_ = false;
  glm::ivec2 cellMarginPx_{0};
  CellView pendingCell_;
  int pendingAdded_ = 0;
  GLuint addSum_ = 0;       // the sum texture addFramebuffer_ was made for
  int requestedWidth_ = 0;  // start's view size (the layers are made on first use)
  int requestedHeight_ = 0;
  gl::Texture depthStencil_;
  gl::Texture partial_;  // RGBA32F at the sum's size: the batch's added views (add_batch.frag)
  gl::Framebuffer addFramebuffer_;
  glm::vec3 pendingBackground_{0.0f};  // the background of the pending added views
  glm::vec4 pendingBackgroundWeight_{0.0f};
  int pending_ = 0;
  int count_ = 0;
  std::vector<glm::vec4> pendingWeights_;     // per view of the batch: channel mask, alpha share
  std::vector<glm::vec2> pendingShifts_;      // per view of the batch: field-curvature shift at r = 1
  std::vector<glm::vec2> pendingJitters_;     // per view of the batch: sub-pixel offset (lens gather)
  std::vector<glm::vec2> pendingBarrelLens_;  // per view of the batch: its aperture point in the barrel's opening
  std::optional<Barrel> barrel_;
  int viewWidth_ = 0;
  int viewHeight_ = 0;
  std::optional<Curvature> curvature_;  // set by start: the field-curvature variant sums the views
  std::vector<PixelBox> region_;        // setRegion's rectangles
  bool regionSet_ = false;
  glm::vec4 weightSum_{0.0f};
  float viewScale_ = 1.0f;
};

}  // namespace lenslab
