#include "render/Renderer.h"

// The per-tile budgets of a frame rendered to a target error (FramePlan::adaptive): Renderer's
// rounds of samples into the tiles that still need them, and each tile's error estimate from its
// two streams. The views it draws are the frame's (Renderer.cpp, drawSample; render/LensViews.h).
#include "gl/Shader.h"
#include "lens/SobolSequence.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

namespace lenslab {
namespace {

constexpr int kErrorBlockPx = 8;  // the error pass sums blocks of 8 × 8 pixels; tiles are whole blocks
int blocksFor(int pixels) { return (pixels + kErrorBlockPx - 1) / kErrorBlockPx; }
// Each tile's estimate is pooled over its 3 × 3 neighbourhood (plan/TileBudget.h pooledMse). On
// rows, occluder and bokeh at 35 and 40 dB (seeds 1-4, 480 px, against 1024-spp ray casts) the
// frames that stopped at their target were optimistic by +0.49 dB on average without it and
// +0.03 dB with it (worst +1.93 and +1.41); a 5 × 5 neighbourhood took another 10-20 % of the
// views for a further -0.2 dB.
constexpr int kPoolRadius = 1;
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

}  // namespace

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
  tilesAtTargetShown_ = 0;
  wholeFrame_ = false;
  rounds_ = 0;
  const std::optional<Accumulator::Curvature> curvature = views_->curvatureWarp();
  const std::optional<Accumulator::Barrel> barrel = views_->barrelMask();
  for (std::unique_ptr<Accumulator>* slot : {&accumulator_, &streamB_}) {
    if (!*slot) *slot = std::make_unique<Accumulator>();
    (*slot)->setExpectedViews(a.maxSamples / 2);  // each stream draws half
    (*slot)->start(size_.widthPx, size_.heightPx, curvature ? &*curvature : nullptr,
                   plan_.remap ? &lensPass_->gather() : nullptr, barrel ? &*barrel : nullptr);
  }
  // The scene passes can be cut to the tiles only where a view's pixel is the sum's pixel, and
  // each view has one aperture point (the barrel's mask is per view).
  scissorViews_ = !plan_.remap && !plan_.fieldCurvature && !viewCamera().lens.hasBarrel();
  const TileGrid previous = grid_;
  grid_ = makeTileGrid(outSize_, a.tileSizePx);
  // About 16 regions of whole tiles, each with its own scramble (see step()).
  regionTiles_ = std::max(1, static_cast<int>(std::lround(std::sqrt(grid_.count() / 16.0))));
  regionColumns_ = (grid_.columns + regionTiles_ - 1) / regionTiles_;
  regionCount_ = regionColumns_ * ((grid_.rows + regionTiles_ - 1) / regionTiles_);
  tiles_.assign(static_cast<std::size_t>(grid_.count()), TileState{});
  rawMse_.assign(tiles_.size(), 0.0);
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

namespace {

// Tiles that have had the same samples go on together: every tile's samples stay a prefix of the
// progressive order (a tile that paused and resumes is not given another tile's next points).
struct TileGroup {
  std::vector<char> selected;
  int wanted = 0;  // the most any of its tiles is expected to need
};

// The tiles given more samples (`more` > 0) in groups, each keyed by the first sample it draws:
// the samples its tiles have had, or with whole views (`wholeFrameFrom`) one group from the most
// samples any tile has (a tile with fewer skips some of the order's points; each point is uniform
// on its own, so its mean stays unbiased).
std::map<int, TileGroup> groupTiles(const std::vector<int>& more, const std::vector<TileState>& tiles,
                                    std::optional<int> wholeFrameFrom) {
  std::map<int, TileGroup> groups;
  for (std::size_t t = 0; t < more.size(); ++t)
    if (more[t] > 0) {
      TileGroup& group = groups[wholeFrameFrom ? *wholeFrameFrom : tiles[t].samples];
      if (group.selected.empty()) {
        group.selected.assign(more.size(), 0);
        group.wanted = more[t];
      }
      group.selected[t] = 1;
      group.wanted = std::max(group.wanted, more[t]);
    }
  return groups;
}

}  // namespace

std::vector<int> Renderer::samplesToAdd(double targetMse) {
  const AdaptivePlan& a = *plan_.adaptive;
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
  return more;
}

int Renderer::drawTileGroup(int first, const std::vector<char>& selected, int wanted) {
  const AdaptivePlan& a = *plan_.adaptive;
  const std::vector<PixelBox> boxes = mergedBoxes(grid_, selected);
  accumulator_->setRegion(&boxes);
  streamB_->setRegion(&boxes);
  // Rounds grow with the count (half of it; each round ends in an estimate, which has its cost),
  // but not past what any of the group's tiles is expected to need; an even number, so that the
  // two streams stay equal.
  const int round = std::max(a.samplesPerRound, first / 2 / 2 * 2);
  const int count = std::min({round, std::max(wanted + (wanted & 1), 2), a.maxSamples - first}) / 2 * 2;
  if (count <= 0) return 0;
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
      std::vector<char> inRegion = selected;
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
      parts.push_back({sobolSample(static_cast<std::uint32_t>(i), regionSeeds[r]),
                       regionBoxes.empty() ? nullptr : &regionBoxes[r]});
    drawSample(parts, sobolStream(i) == 0 ? *accumulator_ : *streamB_, a.lodBias);
  }
  for (std::size_t t = 0; t < selected.size(); ++t)
    if (selected[t]) tiles_[t].samples += count;
  done_ += count;
  return count;
}

bool Renderer::step() {
  if (!adaptive_) throw std::logic_error("Renderer::step without a per-tile plan");
  if (finished_) return false;
  const std::vector<int> more = samplesToAdd(mseFromPsnr(plan_.adaptive->targetPsnrDb));
  const std::map<int, TileGroup> groups =
      groupTiles(more, tiles_, wholeFrame_ ? std::optional(mostSamples()) : std::nullopt);
  if (groups.empty()) {
    finished_ = true;
    return false;
  }
  bool progressed = false;
  for (const auto& [first, group] : groups) progressed |= drawTileGroup(first, group.selected, group.wanted) > 0;
  if (!progressed) {  // every tile going on is at the cap
    finished_ = true;
    return false;
  }
  ++rounds_;
  uploadTileWeights();
  std::vector<char> drawn(more.size(), 0);  // the tiles whose estimates this round changes
  for (std::size_t t = 0; t < more.size(); ++t) drawn[t] = more[t] > 0;
  updateEstimates(drawn);
  return true;
}

const gl::Program& Renderer::streamsProgram(bool errorPerBlock) {
  const bool perPixel = accumulator_->perPixelWeight();  // the lens gather or the barrel weighs each pixel apart
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
  if (accumulator_->perPixelWeight()) return;  // summed per pixel beside the colours
  // Each stream's weight in a tile is its count of samples (a full view adds 1 to every channel
  // and alpha; with axial colour, the three channel views of a sample add 1 to each).
  std::vector<glm::vec4> weights(tiles_.size());
  // Scaled as each view's weight is (Accumulator::setExpectedViews).
  const float scale = accumulator_->viewScale();
  for (std::size_t t = 0; t < tiles_.size(); ++t)
    weights[t] = glm::vec4(scale * static_cast<float>(tiles_[t].samples / 2));
  for (const gl::Texture& w : tileWeights_)
    glTextureSubImage2D(w.id(), 0, 0, 0, grid_.columns, grid_.rows, GL_RGBA, GL_FLOAT, weights.data());
}

void Renderer::bindStreams() {
  glBindTextureUnit(0, accumulator_->sumTexture());
  glBindTextureUnit(1, streamB_->sumTexture());
  if (accumulator_->perPixelWeight()) {
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
  glGetTextureImage(blockError_.id(), 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(blocks.size() * sizeof(glm::vec2)),
                    blocks.data());
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
    rawMse_[static_cast<std::size_t>(t)] = values > 0.5 ? error / values : 0.0;
  }
  std::vector<int> samples(tiles_.size());
  for (std::size_t t = 0; t < tiles_.size(); ++t) samples[t] = tiles_[t].samples;
  const std::vector<double> pooled = pooledMse(grid_, samples, rawMse_, kPoolRadius);
  for (std::size_t t = 0; t < tiles_.size(); ++t) tiles_[t].mse = pooled[t];
}

FrameEstimate Renderer::estimate() const {
  if (!adaptive_ || tiles_.empty()) return {};
  FrameEstimate e = estimateFrame(grid_, tiles_, plan_.adaptive->targetPsnrDb);
  e.rounds = rounds_;
  e.wholeFrame = wholeFrame_;
  if (!finished_) {
    const std::vector<int> more =
        tilesToContinue(grid_, tiles_, mseFromPsnr(plan_.adaptive->targetPsnrDb), plan_.adaptive->maxSamples);
    for (const int m : more) e.tilesActive += m > 0;
  }
  return e;
}

}  // namespace lenslab
