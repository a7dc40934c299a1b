// The cell filter's pass of the accumulator (render/Accumulator.h, accumulate/cell_filter.frag):
// the pending view, spread over its aperture cell's image at each pixel's depth, into the sums.
#include "render/Accumulator.h"

#include "gl/Shader.h"

#include "../../shaders/common/locations.glsl"

#include <cmath>
#include <numbers>

namespace lenslab {

void Accumulator::filterView() {
  if (!cellFilterProgram_)
    cellFilterProgram_ = gl::buildProgram("common/fullscreen.vert", "accumulate/cell_filter.frag");
  const GLuint program = cellFilterProgram_.id();
  const CellView& c = pendingCell_;
  const auto asVec4 = [](const glm::mat2& m) { return glm::vec4(m[0][0], m[0][1], m[1][0], m[1][1]); };
  const glm::vec4 atInfinity = asVec4(c.spreadAtInfinity), perInverseDepth = asVec4(c.spreadPerInverseDepth);
  const float start = static_cast<float>(c.cell.startAngle),
              end = static_cast<float>(c.cell.startAngle + c.cell.sweepAngle);
  const glm::vec2 radii2(static_cast<float>(c.cell.innerRadius * c.cell.innerRadius),
                         static_cast<float>(c.cell.outerRadius * c.cell.outerRadius));
  const glm::vec2 first(std::cos(start), std::sin(start)), last(std::cos(end), std::sin(end));
  glProgramUniform4fv(program, LOCATION_CELL_WEIGHT, 1, &pendingWeights_[0].x);
  glProgramUniform4fv(program, LOCATION_CELL_SPREAD_AT_INFINITY, 1, &atInfinity.x);
  glProgramUniform4fv(program, LOCATION_CELL_SPREAD_PER_INVERSE_DEPTH, 1, &perInverseDepth.x);
  glProgramUniform2fv(program, LOCATION_CELL_INVERSE_DEPTH, 1, &c.inverseDepthFromNdc.x);
  glProgramUniform2fv(program, LOCATION_CELL_LENS_POINT, 1, &c.lensPoint.x);
  glProgramUniform2fv(program, LOCATION_CELL_RADII2, 1, &radii2.x);
  glProgramUniform2fv(program, LOCATION_CELL_FIRST_EDGE, 1, &first.x);
  glProgramUniform2fv(program, LOCATION_CELL_LAST_EDGE, 1, &last.x);
  glProgramUniform1i(program, LOCATION_CELL_WHOLE_RING, c.cell.sweepAngle >= 2.0 * std::numbers::pi ? 1 : 0);
  glProgramUniform1f(program, LOCATION_CELL_AREA, static_cast<float>(c.cell.area()));
  const glm::ivec4 displacements(c.displacementMinPx, c.displacementMaxPx);
  glProgramUniform4iv(program, LOCATION_CELL_DISPLACEMENTS, 1, &displacements.x);
  const glm::vec4 box =
      c.cell.square ? glm::vec4(glm::vec2(c.cell.squareMin), glm::vec2(c.cell.squareMax)) : glm::vec4(0.0f);
  glProgramUniform4fv(program, LOCATION_CELL_SQUARE_BOX, 1, &box.x);
  glProgramUniform2i(program, LOCATION_CELL_MARGIN, cellMarginPx_.x, cellMarginPx_.y);
  glProgramUniform1f(program, LOCATION_CELL_DEPTH_REFERENCE, c.depthReference);
  const ApertureSectors sectors = apertureSectors(c.shape);
  const glm::vec4 sectorAngles(sectors.firstNormalRad, sectors.halfAngleRad, sectors.straight, sectors.round);
  const glm::vec4 sectorScale(sectors.scale, sectors.squeezeRoot, sectors.blades, sectors.twiceArea);
  glProgramUniform4fv(program, LOCATION_CELL_SECTORS, 1, &sectorAngles.x);
  glProgramUniform4fv(program, LOCATION_CELL_SECTOR_SCALE, 1, &sectorScale.x);
  const ApertureCell::Rectangle rectangle = c.cell.momentRectangle(c.shape);
  const glm::vec2 rectangleCentre(rectangle.centre);
  const glm::vec4 rectangleAxes(glm::vec2(rectangle.axis0), glm::vec2(rectangle.axis1));
  glProgramUniform2fv(program, LOCATION_CELL_RECTANGLE_CENTRE, 1, &rectangleCentre.x);
  glProgramUniform4fv(program, LOCATION_CELL_RECTANGLE_AXES, 1, &rectangleAxes.x);
  const gl::DrawTarget three{cellFramebuffer_.id(), sum_->width(), sum_->height()};
  three.bind();
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindTextureUnit(1, depth_.id());
  glBindSampler(1, 0);
  drawViewsInRegion(program);
  glDisable(GL_BLEND);
  pending_ = 0;
}

}  // namespace lenslab
