#include "camera/Rotation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lenslab {

double Quaternion::length() const { return std::sqrt(w * w + x * x + y * y + z * z); }

RotationRows rotationFromQuaternion(const Quaternion& q) {
  const double length = q.length();
  assert(length > 0.0);
  const double w = q.w / length, x = q.x / length, y = q.y / length, z = q.z / length;
  return {glm::dvec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)),
          glm::dvec3(2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)),
          glm::dvec3(2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y))};
}

Quaternion quaternionFromRotation(const RotationRows& r) {
  // 4w² = 1 + r00 + r11 + r22, 4x² = 1 + r00 − r11 − r22, and so on; the off-diagonal sums and
  // differences give the products 4wx = r21 − r12, 4xy = r01 + r10, ...
  const double trace = r[0].x + r[1].y + r[2].z;
  const double squares[4] = {1.0 + trace, 1.0 + r[0].x - r[1].y - r[2].z, 1.0 - r[0].x + r[1].y - r[2].z,
                             1.0 - r[0].x - r[1].y + r[2].z};
  const int largest = static_cast<int>(std::max_element(squares, squares + 4) - squares);
  const double s = 2.0 * std::sqrt(std::max(squares[largest], 0.0));  // 4·|component| / 2 = 2·|component|
  double w = 0.0, x = 0.0, y = 0.0, z = 0.0;
  switch (largest) {
    case 0:
      w = 0.25 * s;
      x = (r[2].y - r[1].z) / s;
      y = (r[0].z - r[2].x) / s;
      z = (r[1].x - r[0].y) / s;
      break;
    case 1:
      x = 0.25 * s;
      w = (r[2].y - r[1].z) / s;
      y = (r[0].y + r[1].x) / s;
      z = (r[0].z + r[2].x) / s;
      break;
    case 2:
      y = 0.25 * s;
      w = (r[0].z - r[2].x) / s;
      x = (r[0].y + r[1].x) / s;
      z = (r[1].z + r[2].y) / s;
      break;
    default:
      z = 0.25 * s;
      w = (r[1].x - r[0].y) / s;
      x = (r[0].z + r[2].x) / s;
      y = (r[1].z + r[2].y) / s;
      break;
  }
  const double sign = w < 0.0 ? -1.0 : 1.0;
  const double length = std::sqrt(w * w + x * x + y * y + z * z);
  return {sign * w / length, sign * x / length, sign * y / length, sign * z / length};
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
