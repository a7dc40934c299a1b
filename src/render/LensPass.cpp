#include "render/LensPass.h"

#include "gl/Shader.h"

#include <stdexcept>

namespace lenslab {
namespace {

// What the tables depend on. The window enters in normalised coordinates, so moving the camera or
// refocusing it (which scales the window with PRP.n) keeps the tables.
std::vector<double> keyOf(const Camera& camera, ImageSize size, const Overscan& overscan) {
  const LensEffects& e = camera.effects;
  const Distortion& d = e.distortion;
  const NormalisedRect n = normalisedWindow(camera.view);
  return {d.k1, d.k2, d.p1, d.p2, d.k3, d.alpha, d.beta, d.gamma, e.chromatic.lateralRed, e.chromatic.lateralBlue,
          n.min.x, n.min.y, n.max.x, n.max.y,
          static_cast<double>(size.widthPx), static_cast<double>(size.heightPx),
          static_cast<double>(overscan.size.widthPx), static_cast<double>(overscan.size.heightPx),
          static_cast<double>(overscan.padPx.x), static_cast<double>(overscan.padPx.y)};
}

}  // namespace

LensPass::LensPass()
    : program_(gl::buildProgram("common/fullscreen.vert", "lens/remap.frag")) {}

void LensPass::prepare(const Camera& camera, ImageSize size, const Overscan& overscan, bool forGather,
                       const TableProgress& progress) {
  const auto rowsOf = [&progress](const char* table) -> RowProgress {
    if (!progress) return {};
    return [&progress, table](int done, int rows) { progress(table, done, rows); };
  };
  std::vector<double> key = keyOf(camera, size, overscan);
  const auto texture = [](GLenum format, ImageSize at, GLenum layout, const void* data) {
    gl::Texture t = gl::Texture::create();
    glTextureStorage2D(t.id(), 1, format, at.widthPx, at.heightPx);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureSubImage2D(t.id(), 0, 0, 0, at.widthPx, at.heightPx, layout, GL_FLOAT, data);
    return t;
  };
  if (key != key_ || tables_.empty()) {
    const RemapTable table = makeRemapTable(camera, size, overscan, rowsOf("inverse"));
    tables_.clear();
    for (const std::vector<glm::vec2>& map : table.channels) tables_.push_back(texture(GL_RG32F, size, GL_RG, map.data()));
    gather_ = {};
    for (int c = 0; c < 3; ++c) gather_.inverse[c] = tables_[table.perChannel() ? static_cast<std::size_t>(c) : 0].id();
    gather_.lateral = table.perChannel();
    gather_.outWidthPx = size.widthPx;
    gather_.outHeightPx = size.heightPx;
    gather_.lateralScale = glm::vec2(1.0 + camera.effects.chromatic.lateralRed, 1.0 + camera.effects.chromatic.lateralBlue);
    if (table.perChannel() && !perChannelProgram_)
      perChannelProgram_ = gl::buildProgram("common/fullscreen.vert", "lens/remap.frag", {"LATERAL_COLOUR"});
    forwardPosition_ = {};
    forwardJacobian_ = {};
    key_ = std::move(key);
    ++tablesBuilt_;
  }
  // The forward tables serve only the per-view gather: a single view (apply) never reads them,
  // and at 20000 px they cost more than the render.
  if (forGather && !forwardPosition_) {
    const ForwardTable forward = makeForwardTable(camera, size, overscan, rowsOf("forward"));
    forwardPosition_ = texture(GL_RGBA32F, forward.size, GL_RGBA, forward.position.data());
    forwardJacobian_ = texture(GL_RGBA32F, forward.size, GL_RGBA, forward.jacobian.data());
    gather_.forwardPosition = forwardPosition_.id();
    gather_.forwardJacobian = forwardJacobian_.id();
    gather_.reachPx = static_cast<float>(forward.reachPx);
    gather_.principalPointPx = glm::vec2(forward.principalPointPx);
  }
}

void LensPass::apply(const gl::RenderTarget& undistorted, const gl::RenderTarget& out) {
  if (tables_.empty()) throw std::logic_error("LensPass::apply before prepare");
  out.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  const bool perChannel = tables_.size() == 3;
  glBindTextureUnit(0, undistorted.colorTexture());
  if (perChannel) {
    glBindTextureUnit(1, tables_[1].id());  // green
    glBindTextureUnit(2, tables_[0].id());  // red
    glBindTextureUnit(3, tables_[2].id());  // blue
  } else {
    glBindTextureUnit(1, tables_[0].id());
  }
  for (GLuint unit = 0; unit <= 3; ++unit) glBindSampler(unit, 0);  // texelFetch only
  fullScreen_.draw(perChannel ? perChannelProgram_ : program_);
}

}  // namespace lenslab
