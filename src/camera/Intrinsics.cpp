#include "camera/Intrinsics.h"

#include "camera/LensMap.h"
#include "core/Error.h"

namespace lenslab {

OpenCvIntrinsics intrinsicsOf(const ViewSpec& view, ImageSize size) {
  if (view.projection != Projection::Perspective)
    throw InputError("OpenCV intrinsics describe a pinhole: a parallel projection has none");
  const Window& w = view.window;
  const double d = view.prp.z;
  OpenCvIntrinsics k;
  k.widthPx = size.widthPx;
  k.heightPx = size.heightPx;
  k.fx = d * size.widthPx / w.width();
  k.fy = d * size.heightPx / w.height();
  // The principal point is the PRP's foot on the view plane; lenslab's pixel x is OpenCV's + 0.5,
  // and OpenCV's y runs down from the window's top (vmax).
  k.cx = (view.prp.x - w.umin) / w.width() * size.widthPx - 0.5;
  k.cy = (w.vmax - view.prp.y) / w.height() * size.heightPx - 0.5;
  return k;
}

OpenCvPose poseOf(const ViewSpec& view) {
  const ViewBasis b = viewBasis(view);
  OpenCvPose pose;
  pose.rows = {b.u, -b.v, -b.n};
  const glm::dvec3 prp = prpWorld(view);
  pose.translation = -glm::dvec3(glm::dot(pose.rows[0], prp), glm::dot(pose.rows[1], prp), glm::dot(pose.rows[2], prp));
  return pose;
}

PinholePlacement placementOf(const OpenCvPose& pose) {
  const RotationRows& r = pose.rows;
  const glm::dvec3& t = pose.translation;
  PinholePlacement p;
  // −Rᵀt: R's columns dotted with t.
  p.eye = -(t.x * r[0] + t.y * r[1] + t.z * r[2]);
  p.vpn = -r[2];
  p.vup = -r[1];
  return p;
}

ViewSpec viewSpecOf(const OpenCvIntrinsics& k, const PinholePlacement& placement, double d) {
  // OpenCV puts pixel centres on integers with (0, 0) the centre of the top-left pixel; lenslab
  // puts them at i + 0.5 with (0, 0) the top-left corner: lenslab x = OpenCV x + 0.5. The image's
  // left edge, lenslab x = 0, is OpenCV x = −0.5; OpenCV's y runs down, the window's v up.
  ViewSpec spec;
  spec.vpn = glm::normalize(placement.vpn);
  spec.vup = placement.vup;
  spec.vrp = placement.eye - d * spec.vpn;
  spec.prp = {0.0, 0.0, d};
  spec.window = {d * (-0.5 - k.cx) / k.fx, -d * (k.heightPx - 0.5 - k.cy) / k.fy, d * (k.widthPx - 0.5 - k.cx) / k.fx,
                 d * (0.5 + k.cy) / k.fy};
  return spec;
}

Camera pinholeFromOpenCv(const OpenCvIntrinsics& k, const Distortion& distortion, const OpenCvPose& pose,
                         const std::string& source) {
  constexpr double kViewPlaneDistance = 1.0;
  ViewSpec spec = viewSpecOf(k, placementOf(pose), kViewPlaneDistance);
  spec.nearDistance = kViewPlaneDistance * kDefaultNearPerViewPlaneDistance;
  validate(spec, source);
  Camera camera = cameraFocusedOnViewPlane(spec, 0.0, source);
  camera.nearFromScene = camera.farFromScene = true;
  camera.calibratedSize = ImageSize{k.widthPx, k.heightPx};
  camera.lens.effects.distortion = distortion;
  validateLensEffects(camera, source);
  return camera;
}

}  // namespace lenslab
