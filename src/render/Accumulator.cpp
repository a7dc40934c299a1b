#include "render/Accumulator.h"

#include "gl/Shader.h"

#include "../../shaders/common/locations.glsl"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace lenslab {
namespace {

constexpr double kBatchMemoryBytes = 256.0 * 1024 * 1024;  // at most this much for the view layers

void drawFullScreen(const gl::FullScreenPass& pass, GLuint program, GLuint texture) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glBindTextureUnit(0, texture);
  glBindSampler(0, 0);
  pass.draw(program);
}

void nearestClamp(GLuint texture) {
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

// A framebuffer drawing into `targets`' colour textures as attachments 0, 1, …
gl::Framebuffer sumFramebuffer(std::initializer_list<const gl::RenderTarget*> targets) {
  gl::Framebuffer fb = gl::Framebuffer::create();
  std::vector<GLenum> buffers;
  for (const gl::RenderTarget* t : targets) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(buffers.size());
    glNamedFramebufferTexture(fb.id(), attachment, t->colorTexture(), 0);
    buffers.push_back(attachment);
  }
  glNamedFramebufferDrawBuffers(fb.id(), static_cast<GLsizei>(buffers.size()), buffers.data());
  if (glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("accumulator: the framebuffer of the sums is incomplete");
  return fb;
}

}  // namespace

Accumulator::Accumulator() : accumulate_(gl::buildProgram("common/fullscreen.vert", "accumulate/accumulate.frag")) {}

void Accumulator::start(int widthPx, int heightPx, const Curvature* curvature, const LensGather* lens,
                        const Barrel* barrel) {
  curvature_ = curvature ? std::optional<Curvature>(*curvature) : std::nullopt;
  lens_ = lens ? std::optional<LensGather>(*lens) : std::nullopt;
  barrel_ = barrel ? std::optional<Barrel>(*barrel) : std::nullopt;
  if (barrel_ && !lens_) {
    gl::Program& program = accumulateBarrel_[curvature_ ? 1 : 0];
    if (!program) {
      std::vector<std::string> defines{"BARREL"};
      if (curvature_) defines.push_back("FIELD_CURVATURE");
      program = gl::buildProgram("common/fullscreen.vert", "accumulate/accumulate.frag", defines);
    }
  }
  if (curvature_ && !accumulateCurved_)
    accumulateCurved_ = gl::buildProgram("common/fullscreen.vert", "accumulate/accumulate.frag", {"FIELD_CURVATURE"});
  if (lens_) {
    gl::Program& gather = gatherLens_[gatherVariant()];
    if (!gather) {
      std::vector<std::string> defines;
      if (curvature_) defines.push_back("FIELD_CURVATURE");
      if (lens_->lateral) defines.push_back("LATERAL_COLOUR");
      if (barrel_) defines.push_back("BARREL");
      gather = gl::buildProgram("common/fullscreen.vert", "accumulate/gather_lens.frag", defines);
    }
  }
  const int sumWidth = lens_ ? lens_->outWidthPx : widthPx - 2 * cellMarginPx_.x,
            sumHeight = lens_ ? lens_->outHeightPx : heightPx - 2 * cellMarginPx_.y;
  if (!sum_ || sum_->width() != sumWidth || sum_->height() != sumHeight) {
    // The old targets go first (the framebuffer holds their storage until it goes): a tiled
    // render's tiles differ in size, and both at once would double the peak.
    gatherFramebuffer_ = {};
    cellFramebuffer_ = {};
    behind_.reset();
    holes_.reset();
    weight_.reset();
    sum_.reset();
    sum_ = std::make_unique<gl::RenderTarget>(sumWidth, sumHeight);
  }
  if ((perPixelWeight() || cellFilter_) && !weight_) weight_ = std::make_unique<gl::RenderTarget>(sumWidth, sumHeight);
  if (perPixelWeight() && !gatherFramebuffer_) gatherFramebuffer_ = sumFramebuffer({sum_.get(), weight_.get()});
  if (cellFilter_ && !behind_) {
    behind_ = std::make_unique<gl::RenderTarget>(sumWidth, sumHeight);
    holes_ = std::make_unique<gl::RenderTarget>(sumWidth, sumHeight);
    cellFramebuffer_ = sumFramebuffer({sum_.get(), weight_.get(), behind_.get(), holes_.get()});
  }
  mayAdd_ = !curvature_ && !lens_ && !barrel_;
  requestedWidth_ = widthPx;
  requestedHeight_ = heightPx;
  if (mayAdd_ && !addBatch_) addBatch_ = gl::buildProgram("common/fullscreen.vert", "accumulate/add_batch.frag");
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (const std::unique_ptr<gl::RenderTarget>* target : {&sum_, &weight_, &behind_, &holes_})
    if (*target) {
      (*target)->bind();
      glClearBufferfv(GL_COLOR, 0, zero);
    }
  // A frame restarted before its views were added leaves them in the partial sum.
  if (partial_) glClearNamedFramebufferfv(addFramebuffer_.id(), GL_COLOR, 0, zero);
  pending_ = 0;
  pendingAdded_ = 0;
  count_ = 0;
  regionSet_ = false;
  weightSum_ = glm::vec4(0.0f);
  pendingBackgroundWeight_ = glm::vec4(0.0f);
  pendingWeights_.assign(kMaxBatch, glm::vec4(0.0f));
  pendingShifts_.assign(kMaxBatch, glm::vec2(0.0f));
  pendingJitters_.assign(kMaxBatch, glm::vec2(0.0f));
  pendingBarrelLens_.assign(kMaxBatch, glm::vec2(0.0f));
}

void Accumulator::allocateAddTarget() {
  int width = 0, height = 0;
  if (depthStencil_) {
    glGetTextureLevelParameteriv(depthStencil_.id(), 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(depthStencil_.id(), 0, GL_TEXTURE_HEIGHT, &height);
  }
  if (width == sum_->width() && height == sum_->height() && addSum_ == sum_->colorTexture()) return;
  addSum_ = sum_->colorTexture();
  addFramebuffer_ = {};  // as allocateLayers: the old storage goes first
  depthStencil_ = {};
  partial_ = {};
  depthStencil_ = gl::Texture::create();
  glTextureStorage2D(depthStencil_.id(), 1, GL_DEPTH32F_STENCIL8, sum_->width(), sum_->height());
  partial_ = gl::Texture::create();
  glTextureStorage2D(partial_.id(), 1, GL_RGBA32F, sum_->width(), sum_->height());
  nearestClamp(partial_.id());
  addFramebuffer_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(addFramebuffer_.id(), GL_COLOR_ATTACHMENT0, partial_.id(), 0);
  glNamedFramebufferTexture(addFramebuffer_.id(), GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_.id(), 0);
  if (glCheckNamedFramebufferStatus(addFramebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("accumulator: the framebuffer that views are added into is incomplete");
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(addFramebuffer_.id(), GL_COLOR, 0, zero);
  // Outside a region no view may add (setRegion); a new target has had none.
  if (regionSet_) resetDepthStencil(1.0f, 1, false);
}

int Accumulator::layersFor(int widthPx, int heightPx) {
  static_assert(kMaxBatch == ACCUMULATE_MAX_BATCH, "the accumulate shaders' arrays hold one batch of views");
  const double bytesPerLayer = 16.0 * widthPx * heightPx;
  return std::clamp(static_cast<int>(kBatchMemoryBytes / bytesPerLayer), 1, kMaxBatch);
}

void Accumulator::allocateLayers(int widthPx, int heightPx) {
  if (viewWidth_ == widthPx && viewHeight_ == heightPx && !framebuffers_.empty()) return;
  viewWidth_ = widthPx;
  viewHeight_ = heightPx;
  const int layers = layersFor(widthPx, heightPx);
  // The old layers are freed before the new are made (a framebuffer keeps a deleted texture's
  // storage alive): tiles of different sizes would otherwise briefly hold both.
  framebuffers_.clear();
  views_ = {};
  depth_ = {};
  views_ = gl::TextureArray::create();
  glTextureStorage3D(views_.id(), 1, GL_RGBA32F, widthPx, heightPx, layers);
  nearestClamp(views_.id());
  depth_ = gl::Texture::create();
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, widthPx, heightPx);
  nearestClamp(depth_.id());  // texelFetch by the cell filter: a complete texture without mipmaps
  for (int layer = 0; layer < layers; ++layer) {
    gl::Framebuffer fb = gl::Framebuffer::create();
    glNamedFramebufferTextureLayer(fb.id(), GL_COLOR_ATTACHMENT0, views_.id(), 0, layer);
    glNamedFramebufferTexture(fb.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    if (glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("accumulator: view layer " + std::to_string(layer) + " is incomplete");
    framebuffers_.push_back(std::move(fb));
  }
}

void Accumulator::resetDepthStencil(float depth, int stencil, bool inRegionOnly) {
  const gl::DrawTarget target{addFramebuffer_.id(), sum_->width(), sum_->height()};
  target.bind();
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  if (inRegionOnly && regionSet_) {
    glEnable(GL_SCISSOR_TEST);
    for (const PixelBox& b : region_) {
      glScissor(b.x, b.y, b.width, b.height);
      glClearBufferfi(GL_DEPTH_STENCIL, 0, depth, stencil);
    }
    glDisable(GL_SCISSOR_TEST);
  } else {
    glDisable(GL_SCISSOR_TEST);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, depth, stencil);
  }
}

Accumulator::View Accumulator::nextView(glm::vec3 background, glm::vec3 channels, glm::vec2 curvatureShiftPx,
                                        glm::vec2 jitterPx, glm::vec2 barrelLens, const CellView* cell) {
  if (!sum_) throw std::logic_error("Accumulator::nextView before start");
  if (cellFilter_ && (!cell || lens_ || curvature_ || barrel_))
    throw std::logic_error("Accumulator::nextView: the cell filter needs each view's cell and no lens effect");
  ++count_;
  // Alpha is shared out so that a full set of channel views adds 1, as one full view does.
  const float channelCount = channels.r + channels.g + channels.b;
  const glm::vec4 weight = viewScale_ * glm::vec4(channels, channelCount / 3.0f);
  weightSum_ += weight;
  if (addsViews()) {
    if (pendingAdded_ == kAddedBatch || (pendingAdded_ > 0 && background != pendingBackground_)) flushBackground();
    allocateAddTarget();
    ++pendingAdded_;
    pendingBackground_ = background;
    pendingBackgroundWeight_ += weight;
    resetDepthStencil(0.0f, 0, true);  // reverse-Z: far is 0; stencil 0: the view may add here
    return {{addFramebuffer_.id(), sum_->width(), sum_->height()}, weight};
  }
  allocateLayers(requestedWidth_, requestedHeight_);
  if (pending_ == batchSize()) flushLayers();
  if (cellFilter_) pendingCell_ = *cell;
  pendingWeights_[static_cast<std::size_t>(pending_)] = weight;
  pendingShifts_[static_cast<std::size_t>(pending_)] = curvatureShiftPx;
  pendingJitters_[static_cast<std::size_t>(pending_)] = jitterPx;
  pendingBarrelLens_[static_cast<std::size_t>(pending_)] = barrelLens;
  return {{framebuffers_[static_cast<std::size_t>(pending_++)].id(), viewWidth_, viewHeight_}, std::nullopt};
}

void Accumulator::flushBackground() {
  if (pendingAdded_ == 0) return;
  pendingAdded_ = 0;
  // The views added weight · (colour − background) where a surface was; weight · background for
  // every pixel of the region completes them. Alpha: the background has no coverage.
  const glm::vec4 colour(pendingBackground_ * glm::vec3(pendingBackgroundWeight_), 0.0f);
  pendingBackgroundWeight_ = glm::vec4(0.0f);
  sum_->bind();
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glProgramUniform4fv(addBatch_.id(), 0, 1, &colour.x);
  // Unit 7 only: a caller may have bound sums on units 0 to 3 already (Renderer::bindStreams).
  glBindTextureUnit(7, partial_.id());
  glBindSampler(7, 0);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (regionSet_) {
    glEnable(GL_SCISSOR_TEST);
    for (const PixelBox& b : region_) {
      glScissor(b.x, b.y, b.width, b.height);
      fullScreen_.draw(addBatch_);
    }
    glDisable(GL_SCISSOR_TEST);
  } else {
    fullScreen_.draw(addBatch_);
  }
  glDisable(GL_BLEND);
  // The partial sum starts again from zero (nothing was added outside the region).
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(addFramebuffer_.id(), GL_COLOR, 0, zero);
}

void Accumulator::flush() {
  flushLayers();
  flushBackground();
}

void Accumulator::flushLayers() {
  if (pending_ == 0) return;
  if (cellFilter_) {
    filterView();
    return;
  }
  if (perPixelWeight()) {
    const gl::DrawTarget both{gatherFramebuffer_.id(), sum_->width(), sum_->height()};
    both.bind();
  } else {
    sum_->bind();
  }
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  const GLuint program = lens_        ? gatherLens_[gatherVariant()].id()
                         : barrel_    ? accumulateBarrel_[curvature_ ? 1 : 0].id()
                         : curvature_ ? accumulateCurved_.id()
                                      : accumulate_.id();
  glProgramUniform1i(program, LOCATION_ACCUMULATE_VIEW_COUNT, pending_);
  glProgramUniform4fv(program, LOCATION_ACCUMULATE_WEIGHTS, pending_, &pendingWeights_[0].x);
  if (curvature_) {
    glProgramUniform2fv(program, LOCATION_ACCUMULATE_SHIFT_PER_RADIUS2, pending_, &pendingShifts_[0].x);
    glProgramUniform2fv(program, LOCATION_ACCUMULATE_NORMALISED_AT_ORIGIN, 1, &curvature_->normalisedAtOrigin.x);
    glProgramUniform2fv(program, LOCATION_ACCUMULATE_NORMALISED_PER_PIXEL, 1, &curvature_->normalisedPerPixel.x);
  }
  if (barrel_ && lens_) {
    // The lens gather masks each sample at its own ray (gather_lens.frag): the opening's
    // coordinates of the views' pixel grid, in units of its radius.
    const glm::vec2 atOrigin = barrel_->reach * barrel_->normalisedAtOrigin,
                    perPixel = barrel_->reach * barrel_->normalisedPerPixel;
    glProgramUniform2fv(program, LOCATION_GATHER_BARREL_AT_ORIGIN, 1, &atOrigin.x);
    glProgramUniform2fv(program, LOCATION_GATHER_BARREL_PER_PIXEL, 1, &perPixel.x);
    glProgramUniform2fv(program, LOCATION_GATHER_BARREL_LENS, pending_, &pendingBarrelLens_[0].x);
  }
  if (barrel_ && !lens_) {
    glProgramUniform2fv(program, LOCATION_ACCUMULATE_NORMALISED_AT_ORIGIN, 1, &barrel_->normalisedAtOrigin.x);
    glProgramUniform2fv(program, LOCATION_ACCUMULATE_NORMALISED_PER_PIXEL, 1, &barrel_->normalisedPerPixel.x);
    glProgramUniform2fv(program, LOCATION_ACCUMULATE_BARREL_LENS, pending_, &pendingBarrelLens_[0].x);
    glProgramUniform1f(program, LOCATION_ACCUMULATE_BARREL_REACH, barrel_->reach);
    glProgramUniform2fv(program, LOCATION_GATHER_JITTER, pending_, &pendingJitters_[0].x);
  }
  if (lens_) {
    glProgramUniform2fv(program, LOCATION_GATHER_JITTER, pending_, &pendingJitters_[0].x);
    glProgramUniform1f(program, LOCATION_GATHER_REACH, lens_->reachPx);
    if (lens_->lateral) {
      glProgramUniform2fv(program, LOCATION_GATHER_PRINCIPAL_POINT, 1, &lens_->principalPointPx.x);
      glProgramUniform2fv(program, LOCATION_GATHER_LATERAL_SCALE, 1, &lens_->lateralScale.x);
    }
    glBindTextureUnit(1, lens_->forwardPosition);
    glBindTextureUnit(2, lens_->forwardJacobian);
    glBindTextureUnit(3, lens_->inverse[1]);
    glBindTextureUnit(4, lens_->inverse[0]);
    glBindTextureUnit(5, lens_->inverse[2]);
    for (GLuint unit = 1; unit <= 5; ++unit) glBindSampler(unit, 0);  // texelFetch only
  }
  drawViewsInRegion(program);
  glDisable(GL_BLEND);
  pending_ = 0;
}

void Accumulator::drawViewsInRegion(GLuint program) const {
  if (!regionSet_) {
    drawFullScreen(fullScreen_, program, views_.id());
    return;
  }
  glEnable(GL_SCISSOR_TEST);
  for (const PixelBox& b : region_) {
    glScissor(b.x, b.y, b.width, b.height);
    drawFullScreen(fullScreen_, program, views_.id());
  }
  glDisable(GL_SCISSOR_TEST);
}

void Accumulator::setRegion(const std::vector<PixelBox>* boxes) {
  flush();
  if (boxes && boxes->size() == 1 && (*boxes)[0] == PixelBox{0, 0, sum_->width(), sum_->height()}) boxes = nullptr;
  regionSet_ = boxes != nullptr;
  if (boxes) region_ = *boxes;
  // Outside the region no view may add: depth at near (nothing is GREATER) and stencil 1.
  if (addSum_ != 0) resetDepthStencil(1.0f, 1, false);
}

GLuint Accumulator::sumTexture() {
  if (!sum_) throw std::logic_error("Accumulator::sumTexture before start");
  flush();
  return sum_->colorTexture();
}

GLuint Accumulator::weightTexture() {
  flush();
  return weight_ && perPixelWeight() ? weight_->colorTexture() : 0;
}

Accumulator::ViewCost Accumulator::viewCost() const {
  // Depth-stencil clear; per batch the partial sum read and cleared, the sum read and written.
  if (addsViews()) return {2.0, 1.0 / kAddedBatch, 8.0 + (16.0 + 16.0 + 32.0) / kAddedBatch};
  const double batch = layersFor(requestedWidth_, requestedHeight_);
  // The layer's clears (colour, depth), its read by the batch sum, and the sum's read and write.
  return {1.0, 1.0 / batch, 16.0 + 4.0 + 16.0 + 32.0 / batch};
}

void Accumulator::resolve(const gl::RenderTarget& out, const VignetteGain* vignetting) {
  if (!sum_ || count_ == 0) throw std::logic_error("Accumulator::resolve with nothing added");
  flush();
  out.bind();
  glDisable(GL_BLEND);
  // The variant: [lens gather's per-pixel weights or the cell filter's fill][vignetting].
  const int kind = perPixelWeight() ? 1 : cellFilter_ ? 2 : 0;
  gl::Program& program = resolvePrograms_[kind][vignetting ? 1 : 0];
  if (!program) {
    std::vector<std::string> defines;
    if (kind == 1) defines.push_back("PER_PIXEL_WEIGHT");
    if (kind == 2) defines.push_back("CELL_FILL");
    if (vignetting) defines.push_back("VIGNETTING");
    program = gl::buildProgram("common/fullscreen.vert", "accumulate/resolve.frag", defines);
  }
  if (vignetting) setVignetteGain(program.id(), *vignetting);
  if (perPixelWeight()) {
    glBindTextureUnit(1, weight_->colorTexture());
    glBindSampler(1, 0);
    drawFullScreen(fullScreen_, program.id(), sum_->colorTexture());
    return;
  }
  if (cellFilter_) {
    glBindTextureUnit(2, weight_->colorTexture());
    glBindTextureUnit(3, behind_->colorTexture());
    glBindTextureUnit(4, holes_->colorTexture());
    for (GLuint unit = 2; unit <= 4; ++unit) glBindSampler(unit, 0);
  }
  const glm::vec4 inverseWeight = glm::vec4(1.0f) / glm::max(weightSum_, glm::vec4(1e-30f));
  glProgramUniform4fv(program.id(), 0, 1, &inverseWeight.x);
  drawFullScreen(fullScreen_, program.id(), sum_->colorTexture());
}

}  // namespace lenslab
