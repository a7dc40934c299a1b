#include "camera/ProjectionCentre.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

ProjectionCentre projectionCentre(const glm::dmat4& clipFromWorld) {
  // Rows x, y and w, each scaled to its largest entry near 1 (the null vector is unchanged; the
  // cofactors below then neither overflow nor underflow for the matrices ScenePass meets).
  glm::dvec4 rows[3];
  const int which[3] = {0, 1, 3};
  for (int k = 0; k < 3; ++k) {
    const int r = which[k];
    glm::dvec4 row(clipFromWorld[0][r], clipFromWorld[1][r], clipFromWorld[2][r], clipFromWorld[3][r]);
    const double largest = std::max({std::abs(row.x), std::abs(row.y), std::abs(row.z), std::abs(row.w)});
    rows[k] = largest > 0.0 && std::isfinite(largest) ? row / largest : row;
  }
  // The null vector h of the 3×4 matrix: h_c = (−1)^c · det(the matrix without column c).
  const auto minor = [&](int skip) {
    glm::dmat3 m;
    for (int k = 0; k < 3; ++k)
      for (int c = 0, j = 0; c < 4; ++c)
        if (c != skip) m[j++][k] = rows[k][c];
    return glm::determinant(m);
  };
  const glm::dvec4 h(minor(0), -minor(1), minor(2), -minor(3));
  ProjectionCentre centre;
  const glm::dvec3 direction(h);
  if (h.w != 0.0) {
    centre.point = direction / h.w;
    if (std::isfinite(centre.point.x) && std::isfinite(centre.point.y) && std::isfinite(centre.point.z)) return centre;
  }
  // At infinity: toward the viewer is where reverse-Z depth (z / w) grows.
  centre.atInfinity = true;
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length)) return centre;
  const glm::dvec3 d = direction / length;
  const double dz = clipFromWorld[0][2] * d.x + clipFromWorld[1][2] * d.y + clipFromWorld[2][2] * d.z;
  centre.towardViewer = dz * clipFromWorld[3][3] >= 0.0 ? d : -d;
  return centre;
}

}  // namespace lenslab
