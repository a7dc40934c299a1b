#pragma once
// Rotations as the vision formats write them. A rotation matrix R is held row by row, as OpenCV
// prints it (X_cam = R·X_world + t). A quaternion is GLM's glm::dquat: (w, x, y, z), w first, in
// the Hamilton convention (i² = j² = k² = ijk = −1; Eigen's), as COLMAP's images.txt writes
// QW QX QY QZ.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>

namespace lenslab {

using RotationRows = std::array<glm::dvec3, 3>;

// R of the unit quaternion q = (w, x, y, z) (q and −q give the same R):
//   | 1 − 2(y² + z²)   2(xy − wz)       2(xz + wy)     |
//   | 2(xy + wz)       1 − 2(x² + z²)   2(yz − wx)     |
//   | 2(xz − wy)       2(yz + wx)       1 − 2(x² + y²) |
// q must have unit length: a quaternion read from a file is normalised where it is read.
RotationRows rotationFromQuaternion(const glm::dquat& q);

// The unit quaternion of a rotation matrix, with w ≥ 0 (of q and −q, the one COLMAP writes).
// glm::quat_cast solves for the largest of |w|, |x|, |y|, |z| first and divides by it, so it
// stays accurate at every angle (the textbook w = ½√(1 + trace) loses all precision near 180°).
glm::dquat quaternionFromRotation(const RotationRows& r);

// How far a matrix is from a rotation: the largest entry of |R·Rᵀ − I|, and det R (+1 for a
// rotation, −1 for a reflection).
struct RotationCheck {
  double orthonormalityError = 0.0;
  double determinant = 0.0;
};
RotationCheck checkRotation(const RotationRows& r);

}  // namespace lenslab
