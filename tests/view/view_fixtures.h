#pragma once
// The camera the view's tests share: rows' camera-dof.json (35 mm f/1.4 focused at 2 m).
#include "camera/PhysicalCamera.h"

namespace lenslab::view::test {

inline PhysicalCamera rowsDof() {
  PhysicalCamera p;
  p.eye = {0.0, 1.0, 3.0};
  p.target = {0.0, 0.55, -2.0};
  p.focalLengthMm = 35.0;
  p.fNumber = 1.4;
  p.focusDistance = 2.0;
  return p;
}

}  // namespace lenslab::view::test
