#include "render/Accumulator.h"

#include "gl/Shader.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace lenslab {
namespace {

constexpr int kMaxBatch = 8;
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

}  // namespace

Accumulator::Accumulator()
    : accumulate_(gl::buildProgram("common/fullscreen.vert", "accumulate/accumulate.frag")),
      resolve_(gl::buildProgram("common/fullscreen.vert", "accumulate/resolve.frag")) {}

void Accumulator::start(int widthPx, int heightPx, const Curvature* curvature, const LensGather* lens) {
  curvature_ = curvature ? std::optional<Curvature>(*curvature) : std::nullopt;
  lens_ = lens ? std::optional<LensGather>(*lens) : std::nullopt;
  if (curvature_ && !accumulateCurved_)
    accumulateCurved_ = gl::buildProgram("common/fullscreen.vert", "accumulate/accumulate.frag", {"FIELD_CURVATURE"});
  if (lens_) {
    gl::Program& gather = gatherLens_[(curvature_ ? 2 : 0) + (lens_->lateral ? 1 : 0)];
    if (!gather) {
      std::vector<std::string> defines;
      if (curvature_) defines.push_back("FIELD_CURVATURE");
      if (lens_->lateral) defines.push_back("LATERAL_COLOUR");
      gather = gl::buildProgram("common/fullscreen.vert", "accumulate/gather_lens.frag", defines);
    }
    if (!resolvePerPixel_)
      resolvePerPixel_ = gl::buildProgram("common/fullscreen.vert", "accumulate/resolve.frag", {"PER_PIXEL_WEIGHT"});
  }
  const int sumWidth = lens_ ? lens_->outWidthPx : widthPx, sumHeight = lens_ ? lens_->outHeightPx : heightPx;
  if (!sum_ || sum_->width() != sumWidth || sum_->height() != sumHeight) {
    // The old targets go first (the framebuffer holds their storage until it goes): a tiled
    // render's tiles differ in size, and both at once would double the peak.
    gatherFramebuffer_ = {};
    weight_.reset();
    sum_.reset();
    sum_ = std::make_unique<gl::RenderTarget>(sumWidth, sumHeight);
  }
  if (lens_ && !weight_) {
    weight_ = std::make_unique<gl::RenderTarget>(sumWidth, sumHeight);
    gatherFramebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(gatherFramebuffer_.id(), GL_COLOR_ATTACHMENT0, sum_->colorTexture(), 0);
    glNamedFramebufferTexture(gatherFramebuffer_.id(), GL_COLOR_ATTACHMENT1, weight_->colorTexture(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(gatherFramebuffer_.id(), 2, buffers);
    if (glCheckNamedFramebufferStatus(gatherFramebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("accumulator: the lens gather's framebuffer is incomplete");
  }
  if (viewWidth_ != widthPx || viewHeight_ != heightPx) {
    viewWidth_ = widthPx;
    viewHeight_ = heightPx;
    const double bytesPerLayer = 16.0 * widthPx * heightPx;
    const int layers = std::clamp(static_cast<int>(kBatchMemoryBytes / bytesPerLayer), 1, kMaxBatch);
    framebuffers_.clear();  // as above: the old layers are freed before the new are made
    views_ = {};
    depth_ = {};
    views_ = gl::TextureArray::create();
    glTextureStorage3D(views_.id(), 1, GL_RGBA32F, widthPx, heightPx, layers);
    nearestClamp(views_.id());
    depth_ = gl::Texture::create();
    glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, widthPx, heightPx);
    for (int layer = 0; layer < layers; ++layer) {
      gl::Framebuffer fb = gl::Framebuffer::create();
      glNamedFramebufferTextureLayer(fb.id(), GL_COLOR_ATTACHMENT0, views_.id(), 0, layer);
      glNamedFramebufferTexture(fb.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
      if (glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("accumulator: view layer " + std::to_string(layer) + " is incomplete");
      framebuffers_.push_back(std::move(fb));
    }
  }
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  sum_->bind();
  glClearBufferfv(GL_COLOR, 0, zero);
  if (weight_) {
    weight_->bind();
    glClearBufferfv(GL_COLOR, 0, zero);
  }
  pending_ = 0;
  count_ = 0;
  regionSet_ = false;
  weightSum_ = glm::vec4(0.0f);
  pendingWeights_.assign(static_cast<std::size_t>(batchSize()), glm::vec4(0.0f));
  pendingShifts_.assign(static_cast<std::size_t>(batchSize()), glm::vec2(0.0f));
  pendingJitters_.assign(static_cast<std::size_t>(batchSize()), glm::vec2(0.0f));
}

gl::DrawTarget Accumulator::nextView(glm::vec3 channels, glm::vec2 curvatureShiftPx, glm::vec2 jitterPx) {
  if (!sum_) throw std::logic_error("Accumulator::nextView before start");
  if (pending_ == batchSize()) flush();
  ++count_;
  // Alpha is shared out so that a full set of channel views adds 1, as one full view does.
  const float channelCount = channels.r + channels.g + channels.b;
  const glm::vec4 weight(channels, channelCount / 3.0f);
  pendingWeights_[static_cast<std::size_t>(pending_)] = weight;
  pendingShifts_[static_cast<std::size_t>(pending_)] = curvatureShiftPx;
  pendingJitters_[static_cast<std::size_t>(pending_)] = jitterPx;
  weightSum_ += weight;
  return {framebuffers_[static_cast<std::size_t>(pending_++)].id(), viewWidth_, viewHeight_};
}

void Accumulator::flush() {
  if (pending_ == 0) return;
  if (lens_) {
    const gl::DrawTarget both{gatherFramebuffer_.id(), sum_->width(), sum_->height()};
    both.bind();
  } else {
    sum_->bind();
  }
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  const GLuint program = lens_ ? gatherLens_[(curvature_ ? 2 : 0) + (lens_->lateral ? 1 : 0)].id()
                       : curvature_ ? accumulateCurved_.id() : accumulate_.id();
  glProgramUniform1i(program, 0, pending_);
  glProgramUniform4fv(program, 1, pending_, &pendingWeights_[0].x);
  if (curvature_) {
    glProgramUniform2fv(program, 9, pending_, &pendingShifts_[0].x);
    glProgramUniform2fv(program, 17, 1, &curvature_->normalisedAtOrigin.x);
    glProgramUniform2fv(program, 18, 1, &curvature_->normalisedPerPixel.x);
  }
  if (lens_) {
    glProgramUniform2fv(program, 19, pending_, &pendingJitters_[0].x);
    glProgramUniform1f(program, 27, lens_->reachPx);
    if (lens_->lateral) {
      glProgramUniform2fv(program, 28, 1, &lens_->principalPointPx.x);
      glProgramUniform2fv(program, 29, 1, &lens_->lateralScale.x);
    }
    glBindTextureUnit(1, lens_->forwardPosition);
    glBindTextureUnit(2, lens_->forwardJacobian);
    glBindTextureUnit(3, lens_->inverse[1]);
    glBindTextureUnit(4, lens_->inverse[0]);
    glBindTextureUnit(5, lens_->inverse[2]);
    for (GLuint unit = 1; unit <= 5; ++unit) glBindSampler(unit, 0);  // texelFetch only
  }
  if (regionSet_) {
    glEnable(GL_SCISSOR_TEST);
    for (const PixelBox& b : region_) {
      glScissor(b.x, b.y, b.width, b.height);
      drawFullScreen(fullScreen_, program, views_.id());
    }
    glDisable(GL_SCISSOR_TEST);
  } else {
    drawFullScreen(fullScreen_, program, views_.id());
  }
  glDisable(GL_BLEND);
  pending_ = 0;
}

void Accumulator::setRegion(const std::vector<PixelBox>* boxes) {
  flush();
  if (boxes && boxes->size() == 1 && (*boxes)[0] == PixelBox{0, 0, sum_->width(), sum_->height()}) boxes = nullptr;
  regionSet_ = boxes != nullptr;
  if (boxes) region_ = *boxes;
}

GLuint Accumulator::sumTexture() {
  if (!sum_) throw std::logic_error("Accumulator::sumTexture before start");
  flush();
  return sum_->colorTexture();
}

GLuint Accumulator::weightTexture() {
  flush();
  return weight_ && lens_ ? weight_->colorTexture() : 0;
}

void Accumulator::resolve(const gl::RenderTarget& out) {
  if (!sum_ || count_ == 0) throw std::logic_error("Accumulator::resolve with nothing added");
  flush();
  out.bind();
  glDisable(GL_BLEND);
  if (lens_) {
    glBindTextureUnit(1, weight_->colorTexture());
    glBindSampler(1, 0);
    drawFullScreen(fullScreen_, resolvePerPixel_.id(), sum_->colorTexture());
    return;
  }
  const glm::vec4 inverseWeight = glm::vec4(1.0f) / glm::max(weightSum_, glm::vec4(1e-30f));
  glProgramUniform4fv(resolve_.id(), 0, 1, &inverseWeight.x);
  drawFullScreen(fullScreen_, resolve_.id(), sum_->colorTexture());
}

}  // namespace lenslab
