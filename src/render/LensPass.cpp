#include "render/LensPass.h"

#include "camera/LensMap.h"
#include "gl/Shader.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>

#include <stdexcept>

namespace lenslab {
namespace {

// What the tables depend on. The window enters in normalised coordinates, so moving the camera or
// refocusing it (which scales the window with PRP.n) keeps the tables.
std::vector<double> keyOf(const ThinLensMap& map) {
  const Camera& camera = map.camera();
  const ImageSize size = map.size();
  const Overscan& overscan = map.overscan();
  const LensEffects& e = camera.lens.effects;
  const Distortion& d = e.distortion;
  const NormalisedRect n = normalisedWindow(camera.view);
  std::vector<double> key;
  for (const DistortionTerm& t : kDistortionTerms) key.push_back(d.*t.value);
  key.insert(key.end(), {e.chromatic.lateralRed, e.chromatic.lateralBlue, n.min.x, n.min.y, n.max.x, n.max.y,
                         static_cast<double>(size.widthPx), static_cast<double>(size.heightPx),
                         static_cast<double>(overscan.size.widthPx), static_cast<double>(overscan.size.heightPx),
                         static_cast<double>(overscan.padPx.x), static_cast<double>(overscan.padPx.y)});
  return key;
}

}  // namespace

LensPass::LensPass() : program_(gl::buildProgram("common/fullscreen.vert", "lens/remap.frag")) {}

void LensPass::prepare(const ThinLensMap& map, bool forGather, const TableProgress& progress) {
  const Camera& camera = map.camera();
  const ImageSize size = map.size();
  std::vector<double> key = keyOf(map);
  const auto texture = [](GLenum format, ImageSize at) {
    gl::Texture t = gl::Texture::create();
    glTextureStorage2D(t.id(), 1, format, at.widthPx, at.heightPx);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
  };
  // Rows per band: each band is filled on every core (8 rows a core keeps them all busy), uploaded,
  // and its buffer reused, so that a table is never whole on the CPU beside its texture (for a
  // 4096-pixel tile that was 1 GB); the caller hears of each band.
  const int band = std::max(kTableBandRows, 8 * tbb::this_task_arena::max_concurrency());
  if (key != key_ || tables_.empty()) {
    // The previous tables go first: a tiled render's tiles each build their own.
    tables_.clear();
    forwardPosition_ = {};
    forwardJacobian_ = {};
    const std::vector<Channel> channels = remappedChannels(camera.lens.effects);
    std::vector<glm::vec2> rows(static_cast<std::size_t>(size.widthPx) *
                                static_cast<std::size_t>(std::min(band, size.heightPx)));
    const int total = static_cast<int>(channels.size()) * size.heightPx;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      gl::Texture t = texture(GL_RG32F, size);
      for (int first = 0; first < size.heightPx; first += band) {
        const int last = std::min(size.heightPx, first + band);
        map.fillRemapRows(channels[c], first, last, rows.data());
        glTextureSubImage2D(t.id(), 0, 0, first, size.widthPx, last - first, GL_RG, GL_FLOAT, rows.data());
        if (progress) progress("inverse", static_cast<int>(c) * size.heightPx + last, total);
      }
      tables_.push_back(std::move(t));
    }
    const bool perChannel = tables_.size() == 3;
    gather_ = {};
    for (int c = 0; c < 3; ++c) gather_.inverse[c] = tables_[perChannel ? static_cast<std::size_t>(c) : 0].id();
    gather_.lateral = perChannel;
    gather_.outWidthPx = size.widthPx;
    gather_.outHeightPx = size.heightPx;
    gather_.lateralScale =
        glm::vec2(1.0 + camera.lens.effects.chromatic.lateralRed, 1.0 + camera.lens.effects.chromatic.lateralBlue);
    if (perChannel && !perChannelProgram_)
      perChannelProgram_ = gl::buildProgram("common/fullscreen.vert", "lens/remap.frag", {"LATERAL_COLOUR"});
    key_ = std::move(key);
    ++tablesBuilt_;
  }
  // The forward tables serve only the per-view gather: a single view (apply) never reads them,
  // and at 20000 px they cost more than the render.
  if (forGather && !forwardPosition_) {
    const ImageSize at = map.overscan().size;
    forwardPosition_ = texture(GL_RGBA32F, at);
    forwardJacobian_ = texture(GL_RGBA32F, at);
    const std::size_t bandTexels =
        static_cast<std::size_t>(at.widthPx) * static_cast<std::size_t>(std::min(band, at.heightPx));
    std::vector<glm::vec4> position(bandTexels), jacobian(bandTexels);
    double halfExtent = 0.0;
    for (int first = 0; first < at.heightPx; first += band) {
      const int last = std::min(at.heightPx, first + band);
      halfExtent = std::max(halfExtent, map.fillForwardRows(first, last, position.data(), jacobian.data()));
      glTextureSubImage2D(forwardPosition_.id(), 0, 0, first, at.widthPx, last - first, GL_RGBA, GL_FLOAT,
                          position.data());
      glTextureSubImage2D(forwardJacobian_.id(), 0, 0, first, at.widthPx, last - first, GL_RGBA, GL_FLOAT,
                          jacobian.data());
      if (progress) progress("forward", last, at.heightPx);
    }
    gather_.forwardPosition = forwardPosition_.id();
    gather_.forwardJacobian = forwardJacobian_.id();
    gather_.reachPx = static_cast<float>(map.forwardReachPx(halfExtent));
    gather_.principalPointPx = glm::vec2(map.forwardPrincipalPointPx());
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
