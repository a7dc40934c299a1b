#pragma once
// Where a view's rays come from, read back from its clipFromWorld: the one point (homogeneous)
// that every clip-space x, y and w plane passes through. A perspective view's centre is its eye
// (for a view through a thin lens, the lens point it was made for); a parallel view's is at
// infinity, and only its direction toward the viewer is known. The shading needs it (the view
// direction v) without asking the camera that made the matrix.
#include <glm/glm.hpp>

namespace lenslab {

struct ProjectionCentre {
  bool atInfinity = false;                 // a parallel projection
  glm::dvec3 point{0.0};                   // the eye, world (perspective only)
  glm::dvec3 towardViewer{0.0, 0.0, 1.0};  // unit (parallel only): the way back along the view rays
};

ProjectionCentre projectionCentre(const glm::dmat4& clipFromWorld);

}  // namespace lenslab
