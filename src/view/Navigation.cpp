#include "view/Navigation.h"

#include "camera/Projection.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lenslab::view {
namespace {

glm::dvec3 point(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }
glm::dvec3 direction(const glm::dmat4& m, const glm::dvec3& d) { return glm::dvec3(m * glm::dvec4(d, 0.0)); }

// Rotation about an axis through `pivot`.
glm::dmat4 rotationAbout(const glm::dvec3& pivot, const glm::dvec3& axis, double radians) {
  return glm::translate(glm::dmat4(1.0), pivot) * glm::rotate(glm::dmat4(1.0), radians, axis) *
         glm::translate(glm::dmat4(1.0), -pivot);
}

EditableCamera rotatedAbout(const EditableCamera& c, const glm::dvec3& pivot, double yaw, double pitch) {
  const ViewBasis b = viewBasis(c.camera.view);
  // Pitch first about the camera's own u, then yaw about world up, so the horizon stays level.
  EditableCamera out = moved(c, rotationAbout(pivot, b.u, pitch));
  return moved(out, rotationAbout(pivot, glm::dvec3(0.0, 1.0, 0.0), yaw));
}

}  // namespace

EditableCamera moved(const EditableCamera& c, const glm::dmat4& worldFromWorld) {
  EditableCamera out = c;
  ViewSpec& s = out.camera.view;
  s.vrp = point(worldFromWorld, s.vrp);
  s.vpn = direction(worldFromWorld, s.vpn);
  s.vup = direction(worldFromWorld, s.vup);
  if (out.physical) {
    out.physical->eye = point(worldFromWorld, out.physical->eye);
    out.physical->target = point(worldFromWorld, out.physical->target);
    out.physical->up = direction(worldFromWorld, out.physical->up);
  }
  return out;
}

glm::dvec3 focusPivotWorld(const Camera& camera) {
  const ViewBasis b = viewBasis(camera.view);
  return camera.view.vrp + camera.view.prp.x * b.u + camera.view.prp.y * b.v;
}

EditableCamera orbited(const EditableCamera& c, double yaw, double pitch) {
  return rotatedAbout(c, focusPivotWorld(c.camera), yaw, pitch);
}

EditableCamera lookedAround(const EditableCamera& c, double yaw, double pitch) {
  return rotatedAbout(c, prpWorld(c.camera.view), yaw, pitch);
}

EditableCamera flown(const EditableCamera& c, glm::dvec3 m) {
  const ViewBasis b = viewBasis(c.camera.view);
  return moved(c, glm::translate(glm::dmat4(1.0), m.x * b.u + m.y * b.v - m.z * b.n));
}

EditableCamera fromPhysical(const PhysicalCamera& physical, const std::string& source, const Lens& lens) {
  validate(physical, "the panel's physical lens");
  return {toCamera(physical, lens, source), physical};
}

}  // namespace lenslab::view
