#include "camera/Rotation.h"

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

// GLM's matrices are column-major (m[column][row]); RotationRows holds rows, so each side is the
// other's transpose.
glm::dmat3 matrixOf(const RotationRows& r) { return glm::transpose(glm::dmat3(r[0], r[1], r[2])); }

RotationRows rowsOf(const glm::dmat3& m) {
  const glm::dmat3 t = glm::transpose(m);
  return {t[0], t[1], t[2]};
}

}  // namespace

RotationRows rotationFromQuaternion(const glm::dquat& q) { return rowsOf(glm::mat3_cast(q)); }

glm::dquat quaternionFromRotation(const RotationRows& r) {
  // Normalised so that a matrix a little off orthonormal (one read from a file) still gives a
  // unit quaternion.
  const glm::dquat q = glm::normalize(glm::quat_cast(matrixOf(r)));
  return q.w < 0.0 ? -q : q;
}

RotationCheck checkRotation(const RotationRows& r) {
  RotationCheck c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      c.orthonormalityError = std::max(c.orthonormalityError, std::abs(glm::dot(r[i], r[j]) - (i == j ? 1.0 : 0.0)));
  c.determinant = glm::dot(r[0], glm::cross(r[1], r[2]));
  return c;
}

}  // namespace lenslab
