#pragma once
// Moving the lecture's camera with the mouse and keys (pure C++, no GL). Every move is a rigid
// motion of the world applied to the viewing description: VRP is a point, VPN and VUP are
// directions, and the PRP and window, given in view-reference coordinates, ride along. A camera
// that came in the physical form moves its eye, target and up the same way, so it stays physical.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"

#include <glm/glm.hpp>

#include <optional>

namespace lenslab::view {

// The camera the demo edits: what renders, and its physical description when it has one.
struct EditableCamera {
  Camera camera;
  std::optional<PhysicalCamera> physical;
};

// Applies worldFromWorld (a rotation and translation) to the camera.
EditableCamera moved(const EditableCamera& camera, const glm::dmat4& worldFromWorld);

// The window's principal point on the view plane (the plane of focus), in world coordinates: the
// point the PRP looks straight at, and the pivot of orbiting.
glm::dvec3 focusPivotWorld(const Camera& camera);

// Orbit about the pivot: yaw about the world up (+y), pitch about the camera's u axis.
EditableCamera orbited(const EditableCamera& camera, double yawRadians, double pitchRadians);
// Look around from the PRP (fly mode): the same rotations about the PRP.
EditableCamera lookedAround(const EditableCamera& camera, double yawRadians, double pitchRadians);
// Move by (right, up, forward) world units along u, v and −n.
EditableCamera flown(const EditableCamera& camera, glm::dvec3 rightUpForward);

// Rebuilds the renderable camera from the physical description (after an edit of it), through
// `lens`'s aperture shape, barrel and effects (the radius is the description's f/2N).
EditableCamera fromPhysical(const PhysicalCamera& physical, const std::string& source, const Lens& lens = {});

}  // namespace lenslab::view
