#include "render/Renderer.h"

#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/Shader.h"
#include "lens/SobolSequence.h"
#include "scene/BlendOrder.h"

#include <cmath>

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

namespace lenslab {
namespace {

constexpr int kErrorBlockPx = 8;  // the error pass sums blocks of 8 × 8 pixels; tiles are whole blocks
int blocksFor(int pixels) { return (pixels + kErrorBlockPx - 1) / kErrorBlockPx; }
// A scissored scene pass costs llvmpipe about as much as drawing 10^4 more pixels on rows
// (lenslab_ratios --breakdown, "16 boxes added" and "10 aligned": 0.2-0.25 ms a box, 0.6-1.4·10^4
// pixels, as much on whole 64-px bins as across them: the pass's draws, not its pixels). Each box
// draws every instance again, so with many triangles a box costs a pass over the geometry.
constexpr double kPixelsPerDrawBox = 1e4;
// What a pixel drawn into scissored tiles costs llvmpipe against one drawn with every tile going
// on: covering boxes larger than their tiles, more passes, and the samples going to the costly
// pixels (textured and blurred) while the cheap ones stop. Measured 1.45 (occluder, 45 dB) and 2.3
// (rows, 40 dB) at 512 px: seconds per sample per pixel of each way to the same target.
constexpr double kTilePixelCost = 1.5;


// The background the accumulator adds for all views at once: the scene's constant colour; none
// with an environment, which each view draws itself (ScenePass), its directions its own.
glm::vec3 constantBackground(const Scene& scene) { return scene.environment ? glm::vec3(0.0f) : scene.lighting.background; }

}  // namespace

Renderer::Renderer(const Scene& scene) : gpuScene_(scene) {}

const gl::RenderTarget& Renderer::target(std::unique_ptr<gl::RenderTarget>& slot, ImageSize size) {
  if (!slot || slot->width() != size.widthPx || slot->height() != size.heightPx) {
    slot.reset();  // freed before the new one is made: a tiled render's tiles differ in size
    slot = std::make_unique<gl::RenderTarget>(size.widthPx, size.heightPx);
  }
  return *slot;
}

Accumulator::Curvature Renderer::normalisedPixels() const {
  return Accumulator::Curvature{glm::vec2(map_->normalisedAtRenderCorner()), glm::vec2(map_->normalisedPerRenderPixel())};
}

std::optional<Accumulator::Barrel> Renderer::barrelMask() const {
  if (!viewCamera().hasBarrel()) return std::nullopt;
  const Accumulator::Curvature pixels = normalisedPixels();
  return Accumulator::Barrel{pixels.normalisedAtOrigin, pixels.normalisedPerPixel,
                             static_cast<float>(viewCamera().barrel.distance / viewCamera().barrel.radius)};
}

std::optional<Accumulator::Curvature> Renderer::curvatureWarp() const {
  if (!plan_.fieldCurvature) return std::nullopt;
  return normalisedPixels();
}

void Renderer::begin(const Camera& camera, const FramePlan& plan, ImageSize size, const LensPass::TableProgress& tables) {
  plan_ = plan;
  // The plan's overscan is for the camera it was made for; a plan reused for another camera
  // without the lens pass (a sweep's ablations) renders that camera's own image.
  map_.emplace(camera, size, plan.remap ? plan.overscan : Overscan{camera, size, {0, 0}});
  size_ = map_->overscan().size;
  outSize_ = size;
  done_ = 0;
  // With distortion or lateral colour the lens gather masks each view's samples at their own
  // undistorted rays (gather_lens.frag, BARREL); a parallel projection has no directions to clip.
  if (camera.hasBarrel() && camera.view.projection != Projection::Perspective)
    throw InputError(cat(camera.source, ": the lens barrel (cat's-eye vignetting) needs a perspective projection; remove \"barrel\""));
  if (plan.vignetting && !vignettePass_) vignettePass_ = std::make_unique<VignettePass>();
  if (plan.remap) {
    if (!lensPass_) lensPass_ = std::make_unique<LensPass>();
    lensPass_->prepare(*map_, plan.apertureSamples > 1, tables);
  }
  adaptive_ = plan.adaptive.has_value();
  if (adaptive_) {
    beginAdaptive();
    return;
  }
  if (plan.apertureSamples <= 1) {
    // No lens: the pinhole view from the PRP, at the pixel centres.
    samples_ = {LensSample{{0.0, 0.0}, {0.0, 0.0}}};
  } else {
    samples_ = makeApertureSamples(plan.pattern, plan.apertureSamples, plan.seed);
    if (!accumulator_) accumulator_ = std::make_unique<Accumulator>();
    const std::optional<Accumulator::Curvature> curvature = curvatureWarp();
    // With distortion or lateral colour each view's samples go straight to where the lens puts
    // them, as the views are summed: no resampling of the mean afterwards.
    const std::optional<Accumulator::Barrel> barrel = barrelMask();
    accumulator_->start(size_.widthPx, size_.heightPx, curvature ? &*curvature : nullptr,
                        plan.remap ? &lensPass_->gather() : nullptr, barrel ? &*barrel : nullptr);
  }
}

void Renderer::drawSample(const std::vector<SamplePart>& parts, Accumulator& sum, float lodBias) {
  const LensSample& first = parts.front().sample;
  const Camera& rendered = viewCamera();
  const Window& w = rendered.view.window;
  const glm::dvec2 pixelSize(w.width() / size_.widthPx, w.height() / size_.heightPx);
  // Field curvature: this view's shift at r = 1, δ·d·κ, in pixels (Accumulator.h); and the sub-pixel
  // offset in view pixels, GL orientation, for the lens gather. Both are the view's, so a view with
  // either is drawn whole from one sample (one part).
  const glm::vec2 curvatureShift(rendered.lensOffset(first.lens) * rendered.view.prp.z *
                                 rendered.effects.fieldCurvature.inverseFocusPerRadius2 / pixelSize);
  const glm::vec2 jitter(static_cast<float>(first.pixel.x), static_cast<float>(-first.pixel.y));
  // Views are added straight into the sum unless the scene's geometry costs more than a layer.
  double triangles = 0.0;
  for (const Instance& instance : gpuScene_.scene().instances)
    triangles += static_cast<double>(gpuScene_.scene().meshes[static_cast<std::size_t>(instance.mesh)].indices.size() / 3);
  // A scene with alphaMode BLEND always: an added view keeps one fragment per pixel, and blend
  // surfaces need every one over what lies behind (ScenePass::drawBlended).
  sum.setLayered(anyBlended(gpuScene_.scene()) ||
                 Accumulator::layersAreCheaper(triangles, static_cast<double>(size_.widthPx) * size_.heightPx));
  const glm::dvec2 lensOffset = rendered.lensOffset(first.lens);
  for (int c = 0; c < plan_.viewsPerSample; ++c) {
    glm::vec3 mask(1.0f);
    // Axial chromatic aberration: each colour has its own plane of focus, so each gets its own
    // view; one view for all is focused as green, on the camera's own plane of focus.
    Channel channel = Channel::Green;
    if (plan_.viewsPerSample == 3) {
      mask = glm::vec3(0.0f);
      mask[c] = 1.0f;
      channel = static_cast<Channel>(c);
    }
    const double shift = rendered.effects.chromatic.inverseFocusShift(channel);
    // The barrel sees this view's aperture point at p·(1 − L/z_f), z_f this channel's focus.
    const glm::vec2 barrelLens = rendered.hasBarrel()
        ? glm::vec2(lensOffset * (1.0 - rendered.barrel.distance * (rendered.inverseFocusDistance() + shift)) / rendered.barrel.radius)
        : glm::vec2(0.0f);
    const Accumulator::View view = sum.nextView(constantBackground(gpuScene_.scene()), mask, curvatureShift, jitter, barrelLens);
    for (const SamplePart& part : parts)
      scenePass_.draw(gpuScene_, map_->clipFromWorld(part.sample, channel), view.target, lodBias, part.boxes,
                      view.addWeight ? &*view.addWeight : nullptr);
  }
}

int Renderer::addSamples(int count) {
  if (adaptive_) throw std::logic_error("Renderer::addSamples on a per-tile plan: use step()");
  // Each view is one of samplesPlanned() jittered samples of every pixel: its texture lookups
  // filter over its share of the pixel (scene.frag).
  const float lodBias = -0.5f * std::log2(static_cast<float>(samplesPlanned()));
  int added = 0;
  for (; added < count && done_ < samplesPlanned(); ++added, ++done_) {
    const LensSample& s = samples_[static_cast<std::size_t>(done_)];
    if (samplesPlanned() == 1) {
      // A single view is the image itself unless a pass follows it (the lens, the vignetting).
      const gl::RenderTarget& out = plan_.remap ? target(undistorted_, size_)
                                    : plan_.vignetting ? target(unvignetted_, size_) : target(output_, size_);
      scenePass_.draw(gpuScene_, map_->clipFromWorld(s, Channel::Green), out.drawTarget(), lodBias);
    } else {
      drawSample({{s, nullptr}}, *accumulator_, lodBias);
    }
  }
  return added;
}

int Renderer::mostSamples() const {
  int most = 0;
  for (const TileState& tile : tiles_) most = std::max(most, tile.samples);
  return most;
}

int Renderer::regionOf(int tile) const {
  return (tile % grid_.columns) / regionTiles_ + regionColumns_ * ((tile / grid_.columns) / regionTiles_);
}

void Renderer::beginAdaptive() {
  const AdaptivePlan& a = *plan_.adaptive;
  samples_.clear();  // progressive: made as they are drawn
  finished_ = false;
  wholeFrame_ = false;
  rounds_ = 0;
  const std::optional<Accumulator::Curvature> curvature = curvatureWarp();
  const std::optional<Accumulator::Barrel> barrel = barrelMask();
  for (std::unique_ptr<Accumulator>* slot : {&accumulator_, &streamB_}) {
    if (!*slot) *slot = std::make_unique<Accumulator>();
    (*slot)->start(size_.widthPx, size_.heightPx, curvature ? &*curvature : nullptr, plan_.remap ? &lensPass_->gather() : nullptr,
                   barrel ? &*barrel : nullptr);
  }
  // The scene passes can be cut to the tiles only where a view's pixel is the sum's pixel, and
  // each view has one aperture point (the barrel's mask is per view).
  scissorViews_ = !plan_.remap && !plan_.fieldCurvature && !viewCamera().hasBarrel();
  const TileGrid previous = grid_;
  grid_ = makeTileGrid(outSize_, a.tileSizePx);
  // About 16 regions of whole tiles, each with its own scramble (see step()).
  regionTiles_ = std::max(1, static_cast<int>(std::lround(std::sqrt(grid_.count() / 16.0))));
  regionColumns_ = (grid_.columns + regionTiles_ - 1) / regionTiles_;
  regionCount_ = regionColumns_ * ((grid_.rows + regionTiles_ - 1) / regionTiles_);
  tiles_.assign(static_cast<std::size_t>(grid_.count()), TileState{});
  for (int t = 0; t < grid_.count(); ++t)
    tiles_[static_cast<std::size_t>(t)].minSamples =
        t < static_cast<int>(a.minSamples.size()) ? a.minSamples[static_cast<std::size_t>(t)] : kMinSamplesBlurredTile;
  // The per-tile textures are kept while the grid is (the view restarts a frame on every change).
  const bool sameGrid = blockError_ && previous.image.widthPx == grid_.image.widthPx &&
                        previous.image.heightPx == grid_.image.heightPx && previous.tileSizePx == grid_.tileSizePx;
  if (sameGrid) return;
  for (gl::Texture& weights : tileWeights_) {
    weights = gl::Texture::create();
    glTextureStorage2D(weights.id(), 1, GL_RGBA32F, grid_.columns, grid_.rows);
  }
  if (a.tileSizePx % kErrorBlockPx != 0) throw std::logic_error("per-tile budgets need tiles of whole 8 x 8 blocks");
  blockError_ = gl::Texture::create();
  glTextureStorage2D(blockError_.id(), 1, GL_RG32F, blocksFor(outSize_.widthPx), blocksFor(outSize_.heightPx));
  blockErrorFramebuffer_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(blockErrorFramebuffer_.id(), GL_COLOR_ATTACHMENT0, blockError_.id(), 0);
}

bool Renderer::step() {
  if (!adaptive_) throw std::logic_error("Renderer::step without a per-tile plan");
  if (finished_) return false;
  const AdaptivePlan& a = *plan_.adaptive;
  const double targetMse = mseFromPsnr(a.targetPsnrDb);
  // Once every tile has its minimum and an estimate, the frame goes on tile by tile only where
  // that is predicted to cost less than whole views (plan/TileBudget.h perTilePays); else it goes
  // on uniformly, all tiles together, to the frame's target. The choice is made once. The regions
  // keep their own scrambles either way: one set of aperture points over the whole frame errs
  // alike everywhere, and the estimate then swings by decibels (+2.3 dB measured on rows at 35 dB).
  if (!wholeFrame_ && rounds_ == 1 && !perTilePays(grid_, tiles_, targetMse, a.maxSamples, kTilePixelCost))
    wholeFrame_ = true;
  std::vector<int> more = tilesToContinue(grid_, tiles_, targetMse, a.maxSamples);
  if (wholeFrame_) {
    const int wanted = wholeFrameMoreSamples(grid_, tiles_, targetMse, a.maxSamples);
    std::fill(more.begin(), more.end(), wanted);
  }
  // Tiles that have had the same samples go on together: every tile's samples stay a prefix of
  // the progressive order (a tile that paused and resumes is not given another tile's next points).
  struct Group {
    std::vector<char> selected;
    int wanted = 0;  // the most any of its tiles is expected to need
  };
  std::map<int, Group> groups;
  std::vector<char> drawn(more.size(), 0);
  for (std::size_t t = 0; t < more.size(); ++t)
    if (more[t] > 0) {
      // Whole views: one group, from the most samples any tile has (a tile with fewer skips some
      // of the order's points; each point is uniform on its own, so its mean stays unbiased).
      Group& group = groups[wholeFrame_ ? mostSamples() : tiles_[t].samples];
      if (group.selected.empty()) {
        group.selected.assign(more.size(), 0);
        group.wanted = more[t];
      }
      group.selected[t] = 1;
      drawn[t] = 1;
      group.wanted = std::max(group.wanted, more[t]);
    }
  if (groups.empty()) {
    finished_ = true;
    return false;
  }
  bool progressed = false;
  for (const auto& [first, group] : groups) {
    const std::vector<PixelBox> boxes = mergedBoxes(grid_, group.selected);
    accumulator_->setRegion(&boxes);
    streamB_->setRegion(&boxes);
    // Rounds grow with the count (half of it; each round ends in an estimate, which has its
    // cost), but not past what any of the group's tiles is expected to need; an even number, so
    // that the two streams stay equal.
    const int round = std::max(a.samplesPerRound, first / 2 / 2 * 2);
    const int count = std::min({round, std::max(group.wanted + (group.wanted & 1), 2), a.maxSamples - first}) / 2 * 2;
    if (count <= 0) continue;
    progressed = true;
    // Each region of tiles draws its own scramble of the sequence (its own seed): the regions'
    // errors are independent, so the frame's error — and its estimate — average over many
    // independent parts instead of following one set of aperture points everywhere (a blurred
    // checkerboard under one set errs alike over the whole floor). The views are drawn in fewer,
    // covering rectangles where a pass costs more than the pixels it saves; only the tiles' exact
    // boxes are added to the sums. Views the lens gather or the field-curvature warp read whole
    // are one part, drawn whole.
    std::vector<std::vector<PixelBox>> regionBoxes;
    std::vector<std::uint32_t> regionSeeds;
    if (scissorViews_) {
      for (int r = 0; r < regionCount_; ++r) {
        std::vector<char> inRegion = group.selected;
        bool any = false;
        for (std::size_t t = 0; t < inRegion.size(); ++t) {
          inRegion[t] = inRegion[t] && regionOf(static_cast<int>(t)) == r;
          any |= inRegion[t] != 0;
        }
        if (!any) continue;
        regionBoxes.push_back(coveringBoxes(mergedBoxes(grid_, inRegion), kPixelsPerDrawBox));
        regionSeeds.push_back(plan_.seed ^ (0x9e3779b9u * static_cast<std::uint32_t>(r + 1)));
      }
    } else {
      regionSeeds.push_back(plan_.seed);
    }
    for (int i = first; i < first + count; ++i) {
      std::vector<SamplePart> parts;
      for (std::size_t r = 0; r < regionSeeds.size(); ++r)
        parts.push_back({sobolSample(static_cast<std::uint32_t>(i), regionSeeds[r]), regionBoxes.empty() ? nullptr : &regionBoxes[r]});
      drawSample(parts, sobolStream(i) == 0 ? *accumulator_ : *streamB_, a.lodBias);
    }
    for (std::size_t t = 0; t < group.selected.size(); ++t)
      if (group.selected[t]) tiles_[t].samples += count;
    done_ += count;
  }
  if (!progressed) {  // every tile going on is at the cap
    finished_ = true;
    return false;
  }
  ++rounds_;
  uploadTileWeights();
  updateEstimates(drawn);
  return true;
}

const gl::Program& Renderer::streamsProgram(bool errorPerBlock) {
  const bool perPixel = plan_.remap;  // the lens gather weighs each pixel apart
  gl::Program& program = streams_[(perPixel ? 2 : 0) + (errorPerBlock ? 1 : 0)];
  if (!program) {
    std::vector<std::string> defines;
    if (perPixel) defines.push_back("PER_PIXEL_WEIGHT");
    if (errorPerBlock) defines.push_back("ERROR_PER_BLOCK");
    program = gl::buildProgram("common/fullscreen.vert", "accumulate/two_streams.frag", defines);
  }
  return program;
}

void Renderer::uploadTileWeights() {
  if (plan_.remap) return;  // the lens gather sums its weights per pixel
  // Each stream's weight in a tile is its count of samples (a full view adds 1 to every channel
  // and alpha; with axial colour, the three channel views of a sample add 1 to each).
  std::vector<glm::vec4> weights(tiles_.size());
  for (std::size_t t = 0; t < tiles_.size(); ++t) weights[t] = glm::vec4(static_cast<float>(tiles_[t].samples / 2));
  for (const gl::Texture& w : tileWeights_)
    glTextureSubImage2D(w.id(), 0, 0, 0, grid_.columns, grid_.rows, GL_RGBA, GL_FLOAT, weights.data());
}

void Renderer::bindStreams() {
  glBindTextureUnit(0, accumulator_->sumTexture());
  glBindTextureUnit(1, streamB_->sumTexture());
  if (plan_.remap) {
    glBindTextureUnit(2, accumulator_->weightTexture());
    glBindTextureUnit(3, streamB_->weightTexture());
  } else {
    glBindTextureUnit(2, tileWeights_[0].id());
    glBindTextureUnit(3, tileWeights_[1].id());
  }
  for (GLuint unit = 0; unit <= 3; ++unit) glBindSampler(unit, 0);  // texelFetch only
}

void Renderer::updateEstimates(const std::vector<char>& drawn) {
  const gl::Program& program = streamsProgram(true);
  bindStreams();
  const int blocksX = blocksFor(outSize_.widthPx), blocksY = blocksFor(outSize_.heightPx);
  const gl::DrawTarget errors{blockErrorFramebuffer_.id(), blocksX, blocksY};
  errors.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glProgramUniform1i(program.id(), 0, grid_.tileSizePx);
  // Only the tiles drawn this round have changed.
  const int blocksPerTile = grid_.tileSizePx / kErrorBlockPx;
  glEnable(GL_SCISSOR_TEST);
  for (const PixelBox& b : mergedBoxes(grid_, drawn)) {
    glScissor(b.x / kErrorBlockPx, b.y / kErrorBlockPx, blocksFor(b.x + b.width) - b.x / kErrorBlockPx,
              blocksFor(b.y + b.height) - b.y / kErrorBlockPx);
    fullScreen_.draw(program);
  }
  glDisable(GL_SCISSOR_TEST);
  std::vector<glm::vec2> blocks(static_cast<std::size_t>(blocksX) * static_cast<std::size_t>(blocksY));
  glGetTextureImage(blockError_.id(), 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(blocks.size() * sizeof(glm::vec2)), blocks.data());
  for (int t = 0; t < grid_.count(); ++t) {  // tiles and blocks both count rows from the bottom
    if (!drawn[static_cast<std::size_t>(t)]) continue;
    const int bx0 = (t % grid_.columns) * blocksPerTile, by0 = (t / grid_.columns) * blocksPerTile;
    double error = 0.0, values = 0.0;
    for (int by = by0; by < std::min(by0 + blocksPerTile, blocksY); ++by)
      for (int bx = bx0; bx < std::min(bx0 + blocksPerTile, blocksX); ++bx) {
        const glm::vec2 e = blocks[static_cast<std::size_t>(by * blocksX + bx)];
        error += e.x;
        values += e.y;
      }
    tiles_[static_cast<std::size_t>(t)].mse = values > 0.5 ? error / values : 0.0;
  }
}

FrameEstimate Renderer::estimate() const {
  if (!adaptive_ || tiles_.empty()) return {};
  FrameEstimate e = estimateFrame(grid_, tiles_, plan_.adaptive->targetPsnrDb);
  e.rounds = rounds_;
  e.wholeFrame = wholeFrame_;
  if (!finished_) {
    const std::vector<int> more = tilesToContinue(grid_, tiles_, mseFromPsnr(plan_.adaptive->targetPsnrDb), plan_.adaptive->maxSamples);
    for (const int m : more) e.tilesActive += m > 0;
  }
  return e;
}

Image Renderer::resolve() {
  const gl::RenderTarget& out = resolveOnGpu();
  glFinish();
  return out.readColor();
}

void Renderer::complete(const std::function<void()>& afterBatch) {
  if (adaptive_) {
    while (step())
      if (afterBatch) afterBatch();
    return;
  }
  const int batch = std::max(1, plan_.apertureSamples / 50);
  while (done_ < samplesPlanned()) {
    addSamples(batch);
    if (afterBatch) afterBatch();
  }
}

Renderer::Progress Renderer::progress() const {
  if (adaptive_) {
    const FrameEstimate e = estimate();
    return {e.tiles - e.tilesActive, e.tiles};
  }
  return {done_, samplesPlanned()};
}

int Renderer::progressTotal(const FramePlan& plan, ImageSize size) {
  return plan.adaptive ? makeTileGrid(size, plan.adaptive->tileSizePx).count() : std::max(plan.apertureSamples, 1);
}

Image Renderer::render(const Camera& camera, const FramePlan& plan, ImageSize size) {
  begin(camera, plan, size);
  complete();
  return resolve();
}

const gl::RenderTarget& Renderer::renderPinhole(const Camera& camera, ImageSize size) {
  const gl::RenderTarget& v = target(view_, size);
  scenePass_.draw(gpuScene_, clipFromWorld(camera.view), v.drawTarget());
  glFinish();
  return v;
}

std::vector<float> Renderer::pinholeDepth(const Camera& camera, ImageSize size) {
  return renderPinhole(camera, size).readDepth();
}

const gl::RenderTarget& Renderer::resolveOnGpu() {
  if (done_ == 0) throw std::logic_error("Renderer::resolve before any sample");
  const gl::RenderTarget& out = target(output_, outSize_);
  const VignetteGain gain = vignetteGainFor(map_->camera(), outSize_);
  // A resolve of many views is the frame's last pass and multiplies the gain in itself.
  if (!adaptive_ && samplesPlanned() > 1) {  // the lens, if any, was applied as the views were summed
    accumulator_->resolve(out, plan_.vignetting ? &gain : nullptr);
    return out;
  }
  // Else the vignetting pass follows, reading a target of its own: each resolve then applies the
  // gain once, however often a progressive frame is resolved.
  const gl::RenderTarget& resolved = plan_.vignetting ? target(unvignetted_, outSize_) : out;
  if (adaptive_) {
    const gl::Program& program = streamsProgram(false);
    bindStreams();
    resolved.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glProgramUniform1i(program.id(), 0, grid_.tileSizePx);
    fullScreen_.draw(program);
  } else if (plan_.remap) {
    lensPass_->apply(target(undistorted_, size_), resolved);
  }  // else a single view drawn straight into `resolved` (addSamples)
  if (plan_.vignetting) vignettePass_->apply(gain, resolved, out);
  return out;
}

}  // namespace lenslab
