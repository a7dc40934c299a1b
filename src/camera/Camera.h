#pragma once
// Everything the renderers need to know about the camera: the lecture's viewing description and
// the lens. Where it came from is kept for messages and --stats.
#include "camera/ViewSpec.h"

#include <string>

namespace lenslab {

struct Camera {
  ViewSpec view;
  double apertureRadius = 0.0;  // world units; 0 = pinhole (depth of field: issue #3)
  std::string source;           // "assets/rows/camera.json", "glTF camera 0 (Main)", "auto framing"
};

}  // namespace lenslab
