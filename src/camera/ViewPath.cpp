#include "camera/ViewPath.h"

#include "camera/Intrinsics.h"
#include "camera/Rotation.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/effects/LensEffectRegistry.h"

#include <cmath>
#include <limits>

namespace lenslab {
namespace {

// A key as a pinhole: the PRP in the world, the camera's rotation (OpenCV's R as a quaternion),
// its K at the keys' size.
struct Pinhole {
  glm::dvec3 eye{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  OpenCvIntrinsics k;
};

ImageSize keySize(const CameraPath& path) {
  return path.viewKeys.front().camera.calibratedSize.value_or(kNominalViewKeySize);
}

Pinhole pinholeOf(const Camera& camera, ImageSize size) {
  const OpenCvPose pose = poseOf(camera.view);
  return {placementOf(pose).eye, quaternionFromRotation(pose.rows), intrinsicsOf(camera.view, size)};
}

}  // namespace

void validateViewKeys(const std::vector<ViewPathKey>& keys, std::string_view where) {
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const Camera& c = keys[i].camera;
    const std::string key = cat(where, ": keys[", i, "]");
    if (c.view.projection != Projection::Perspective)
      throw InputError(cat(key, ": a parallel projection has no pinhole to move along a path; give perspective keys"));
    const Camera& first = keys.front().camera;
    if (c.calibratedSize.has_value() != first.calibratedSize.has_value() ||
        (c.calibratedSize && (c.calibratedSize->widthPx != first.calibratedSize->widthPx ||
                              c.calibratedSize->heightPx != first.calibratedSize->heightPx)))
      throw InputError(cat(key,
                           ": its image size differs from the first key's; every key's K must be for one image size "
                           "(scale K to it: fx, cx by the width ratio, fy, cy by the height ratio)"));
    if (c.lens.aperture != first.lens.aperture)
      throw InputError(cat(key, ": \"aperture\" is ", describeAperture(c.lens.aperture), " where the first key's is ",
                           describeAperture(first.lens.aperture),
                           "; every key of a path takes the same aperture shape"));
    if (c.lens.barrel != first.lens.barrel)
      throw InputError(
          cat(key, ": \"barrel\" differs from the first key's; every key of a path takes the same lens barrel"));
    if (c.lens.effects.distortion.fisheye != first.lens.effects.distortion.fisheye)
      throw InputError(cat(key,
                           ": \"distortion.model\" differs from the first key's; every key of a path takes one "
                           "distortion model (fisheye or opencv), whose coefficients are interpolated"));
  }
}

Camera viewCameraAt(const CameraPath& path, double timeSeconds, const std::string& source) {
  const std::vector<ViewPathKey>& keys = path.viewKeys;
  const ImageSize size = keySize(path);
  std::vector<double> times, inverseFocus;
  std::vector<glm::dvec3> eyes;
  std::vector<Pinhole> pinholes;
  for (const ViewPathKey& key : keys) {
    times.push_back(key.timeSeconds);
    inverseFocus.push_back(key.camera.inverseFocusDistance());
    pinholes.push_back(pinholeOf(key.camera, size));
    eyes.push_back(pinholes.back().eye);
  }
  const bool single = keys.size() == 1;
  const PathSegment s = single ? PathSegment{0, 0.0} : segmentAt(times, timeSeconds);
  const std::size_t k = s.index, next = single ? 0 : k + 1;
  const double u = s.u;
  const Camera& a = keys[k].camera;
  const Camera& b = keys[next].camera;
  const Pinhole& pa = pinholes[k];
  const Pinhole& pb = pinholes[next];
  const bool smooth = path.interpolation == PathInterpolation::Smooth;

  Pinhole p;
  p.eye = single ? pa.eye : smooth ? splineThrough(eyes, k, u) : pa.eye + (pb.eye - pa.eye) * u;
  p.rotation = u == 0.0 ? pa.rotation : u == 1.0 ? pb.rotation : glm::slerp(pa.rotation, pb.rotation, u);
  p.k = pa.k;
  p.k.fx = lerp(pa.k.fx, pb.k.fx, u), p.k.fy = lerp(pa.k.fy, pb.k.fy, u);
  p.k.cx = lerp(pa.k.cx, pb.k.cx, u), p.k.cy = lerp(pa.k.cy, pb.k.cy, u);
  const double inverse = single   ? inverseFocus[0]
                         : smooth ? monotoneCubic(times, inverseFocus, timeSeconds)
                                  : lerp(inverseFocus[k], inverseFocus[next], u);
  const double focus = inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();

  // The view as the OpenCV form builds one from R and t (io/OpenCvCameraJson.cpp): the view plane
  // on the plane of focus, or at unit distance with the focus held as 1/z_f.
  const RotationRows r = rotationFromQuaternion(glm::normalize(p.rotation));
  const PinholePlacement placement{p.eye, -r[2], -r[1]};
  const double d = viewPlaneDistanceFor(focus, 1.0);
  ViewSpec spec = viewSpecOf(p.k, placement, d);
  spec.nearDistance = lerp(a.view.nearDistance, b.view.nearDistance, u);
  spec.farDistance = lerpDistance(a.view.farDistance, b.view.farDistance, u);
  validate(spec, source);
  Camera camera = cameraFocusedOnViewPlane(spec, 0.0, source);
  camera.lens = interpolateLens(a.lens, b.lens, u);
  if (d != focus) camera.inverseFocusOffPlane = inverse;
  camera.nearFromScene = path.nearFromScene;
  camera.farFromScene = path.farFromScene;
  if (a.calibratedSize) camera.calibratedSize = size;
  return camera;
}

void validateViewFrames(const CameraPath& path, std::string_view where) {
  validateViewKeys(path.viewKeys, where);
  const int frames = path.frameCount();
  for (int frame = 0; frame < frames; ++frame) {
    const double t = path.frameTimeSeconds(frame);
    viewCameraAt(path, t, cat(where, ": frame ", frame, " (t = ", t, " s)"));
  }
}

}  // namespace lenslab
