#pragma once
// The lecture's diagram of the camera, as world-space line segments (pure C++, no GL): the PRP, the
// window on the view plane (the plane of focus), the view volume from the PRP through the window's
// corners, the aperture disk in the PRP's plane with the aperture sample points, and a few rays
// from aperture points through one window point. The outside view draws them over the scene.
#include "camera/Camera.h"
#include "lens/AperturePattern.h"

#include <glm/glm.hpp>

#include <vector>

namespace lenslab::view {

struct DiagramLine {
  glm::dvec3 from;
  glm::dvec3 to;
  glm::vec3 color;  // display (sRGB-encoded) colour
};

struct DiagramColors {
  glm::vec3 prp{1.0f, 0.9f, 0.2f};
  glm::vec3 window{1.0f, 1.0f, 1.0f};
  glm::vec3 volume{0.75f, 0.8f, 0.9f};
  glm::vec3 aperture{0.3f, 0.9f, 1.0f};
  glm::vec3 sampleDone{1.0f, 0.55f, 0.1f};
  glm::vec3 samplePending{0.45f, 0.3f, 0.2f};
  glm::vec3 ray{1.0f, 0.25f, 0.25f};
};

struct DiagramStyle {
  double volumeDepthScale = 2.5;  // how far the view volume and rays go, in multiples of PRP.n
  int rayCount = 6;               // rays from aperture samples through the window centre
  // The aperture (a few mm) is tiny beside a window of metres: the disk, its sample points and the
  // rays' origins may be drawn enlarged by this factor (the panel says so when it is not 1).
  double apertureScale = 1.0;
  DiagramColors colors;
};

// `samples` are the planned aperture samples (on the unit disk), the first `samplesDone` of them
// already accumulated.
std::vector<DiagramLine> lectureDiagram(const Camera& camera, const std::vector<LensSample>& samples, int samplesDone,
                                        const DiagramStyle& style = {});

// An aperture scale that draws the disk at least `fraction` of the window's height across (1 when
// it is already that large, or for a pinhole).
double readableApertureScale(const Camera& camera, double fraction = 0.25);

}  // namespace lenslab::view
