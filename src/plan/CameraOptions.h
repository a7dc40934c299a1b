#pragma once
// The camera a user asks for in words (the command line's strings): which camera of the scene, which
// animation clip, and the lens and pose that override the chosen camera field by field. Pure (no
// command-line library): src/app registers these as options; the viewer and the tests use them too.
//
// Composition: a base camera comes first, from one source (plan/CameraSelection.h picks it: a camera
// file, a glTF camera, or automatic framing); the options then win field by field:
//
// | base                                   | --focal-length, --sensor, --f-number   | --eye, --target                    |
// |----------------------------------------|----------------------------------------|------------------------------------|
// | physical form (a file, automatic       | set that field (a new focal length or  | set that field; a base focused on  |
// | framing, a capture path's key)         | sensor changes the field of view)      | its target stays focused on it     |
// | glTF perspective camera                | becomes the physical form first: its   | replace the node's pose (up +Y)    |
// |                                        | sensor --sensor or 24 mm high at its   |                                    |
// |                                        | aspect, focal length h / 2·tan(yfov/2) |                                    |
// | glTF orthographic camera               | refused (no lens), but f-number        | replace the node's pose (up +Y)    |
// |                                        | infinity                               |                                    |
// | lecture or OpenCV-intrinsics form      | --f-number needs --focal-length (the   | refused: edit the file's VRP/VPN/  |
// |                                        | aperture radius f/2N; the view stays); | PRP, or eye/target                 |
// |                                        | --sensor or a lone --focal-length      |                                    |
// |                                        | refused                                |                                    |
//
// A COLMAP image's camera (--colmap DIR --image NAME) is a base in the OpenCV-intrinsics form.
//
// Automatic framing takes the lens and sensor from the options (default 35 mm on 36×24 mm) and
// frames the scene's bounding sphere with them (camera/AutoFraming.h); --eye and --target place it
// instead (only --target: the framing's view of a sphere about the target; only --eye: looking at
// the sphere's centre). A refusal is one line naming the option, the base camera and what to do.
#include "camera/PhysicalCamera.h"
#include "plan/SceneChoice.h"  // which glTF camera and clip: the options name them
#include "plan/UserOptions.h"
#include "scene/BoundingSphere.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct CameraOptions {
  std::optional<double> focalLengthMm;  // --focal-length MM
  std::string fNumber;                  // --f-number: N, or infinity / pinhole (no aperture); empty = the base's
  std::string sensor;                   // --sensor: WxH in mm, or a name (namedSensors); empty = the base's
  std::optional<glm::dvec3> eye;        // --eye X,Y,Z: the lens centre, world units
  std::optional<glm::dvec3> target;     // --target X,Y,Z: the point looked at, world units
  std::string cameraNode;               // --camera-node: a glTF camera by node name, camera name or index
  std::string animation;                // --animation: a clip by name or index, or all; empty = the first
  std::string colmapDir;                // --colmap DIR: a COLMAP text model (cameras.txt, images.txt)
  std::string colmapImage;              // --image NAME: the photograph of that model whose camera to use

  // Whether an option names the base camera (a glTF camera or a COLMAP image): a command's default
  // camera file then stays out of it.
  bool namesBaseCamera() const { return !cameraNode.empty() || !colmapDir.empty() || !colmapImage.empty(); }

  bool changesLens() const { return focalLengthMm.has_value() || !fNumber.empty() || !sensor.empty(); }
  bool changesPose() const { return eye.has_value() || target.has_value(); }
  // The lens and pose options given, as typed (e.g. "--focal-length 50 --f-number 2"), for messages.
  std::string describe() const;
};

// Sensor sizes by name, in millimetres.
struct NamedSensor {
  const char* name;
  glm::dvec2 sizeMm;
  const char* note = "";  // for the list in --sensor's help, after the size; "" for none
};
const std::vector<NamedSensor>& namedSensors();
// namedSensors for help and messages: "full-frame (36x24), aps-c (23.6x15.6, Nikon's and Sony's;
// Canon's is --sensor 22.3x14.9), micro-four-thirds (17.3x13), 1-inch (13.2x8.8)".
std::string namedSensorList();

// --sensor's text: a name, or WIDTHxHEIGHT in millimetres (x or X). Throws InputError naming the
// option and what would be valid.
glm::dvec2 parseSensorMm(const std::string& text);
// --f-number's text: a positive number, or infinity / pinhole (+infinity: no aperture).
double parseFNumber(const std::string& text);

// Where a command's base camera came from, which decides what the options may change.
enum class CameraForm { Physical, Lecture, Intrinsics, GltfPerspective, GltfOrthographic, AutomaticFraming };

struct BaseCamera {
  CameraForm form = CameraForm::AutomaticFraming;
  std::string name;                // for messages: "cam.json", "glTF camera 1 (node \"Top\")", "automatic framing"
  SelectedCamera selected;         // file forms: the file's camera
  SceneCamera gltf;                // glTF forms: the camera where its (posed) node puts it
  std::size_t gltfIndex = 0;       //   its index in scene.cameras
  double gltfFocusDistance = 1.0;  // glTF forms: where the view plane (the plane of focus) goes
  BoundingSphere subject;          // automatic framing: what it frames
};

// A glTF camera as a base: focus (glTF cameras have none) at the depth of the scene's centre along
// its view, no nearer than twice znear.
BaseCamera gltfBaseCamera(const Scene& scene, std::size_t index);
// Automatic framing of the scene's bounding sphere.
BaseCamera framingBaseCamera(const Scene& scene);

// The base with the options applied, field by field (the table above). `imageAspect` is
// --width / --height when both are given (0 otherwise), for glTF cameras without an aspect ratio.
// Throws InputError (one line: the option, the base camera, what to do) for an option the base
// cannot take, and for the physical checks of the result (focus beyond the focal length, ...).
SelectedCamera composeCamera(const BaseCamera& base, const CameraOptions& options, double imageAspect);

// A glTF perspective camera as a physical description with the options applied (validated): what
// composeCamera renders once an option is given, and what capture writes for each frame of a glTF
// camera. Its near is the camera's znear, its far its zfar.
PhysicalCamera gltfPhysicalCamera(const BaseCamera& base, const CameraOptions& options, double imageAspect);

// The options applied to one physical description (the physical-form rows of the table); `where`
// names it in errors. What capture does to each frame's camera.
PhysicalCamera withCameraOptions(PhysicalCamera camera, const CameraOptions& options, const std::string& where);

// What --focus-distance, --focus-at, --blades and --squeeze cannot do on `camera`: without an
// aperture (a pinhole) focus and the aperture's shape change nothing. One warning per option given, each naming it and what to do.
std::vector<std::string> focusWarnings(const Camera& camera, const LensOptions& lens);

}  // namespace lenslab
