#include "camera/Intrinsics.h"

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

}  // namespace lenslab
