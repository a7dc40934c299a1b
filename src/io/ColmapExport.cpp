#include "io/ColmapExport.h"

#include "core/Error.h"
#include "core/Text.h"

#include <charconv>

namespace lenslab {

namespace {

// The shortest decimal that reads back as the same double (−0 written as 0).
std::string shortest(double value) {
  if (value == 0.0) return "0";
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, error == std::errc() ? end : buffer);
}

}  // namespace

ColmapCamera colmapCameraOf(const OpenCvIntrinsics& k, const Distortion& d, std::uint32_t id,
                            const std::string& where) {
  if (d.alpha != 0.0 || d.gamma != 0.0)
    throw InputError(cat(where, ": the lens has the lecture's odd-power distortion (alpha ", d.alpha, ", gamma ",
                         d.gamma,
                         "), which no COLMAP camera model holds; give the distortion as OpenCV's k1, k2, p1, p2, k3"));
  if (d.s1 != 0.0 || d.s2 != 0.0 || d.s3 != 0.0 || d.s4 != 0.0)
    throw InputError(cat(where, ": the lens has OpenCV's thin-prism terms (s1 ", d.s1, ", s2 ", d.s2, ", s3 ", d.s3,
                         ", s4 ", d.s4,
                         "), which no COLMAP camera model holds; COLMAP's fullest, FULL_OPENCV, stops at k6"));
  ColmapCamera c;
  c.id = id;
  c.widthPx = k.widthPx;
  c.heightPx = k.heightPx;
  // COLMAP's pixel centres are at i + 0.5, OpenCV's at i.
  c.params = {k.fx, k.fy, k.cx + 0.5, k.cy + 0.5};
  if (d.fisheye) {
    c.model = "OPENCV_FISHEYE";
    c.params.insert(c.params.end(), {d.k1, d.k2, d.k3, d.k4});
    return c;
  }
  const double k1 = d.k1 + d.beta;  // β is the r² coefficient, as k1 is
  const bool rational = d.k3 != 0.0 || d.k4 != 0.0 || d.k5 != 0.0 || d.k6 != 0.0;
  if (k1 == 0.0 && d.k2 == 0.0 && d.p1 == 0.0 && d.p2 == 0.0 && !rational) {
    c.model = "PINHOLE";
  } else if (!rational) {
    c.model = "OPENCV";
    c.params.insert(c.params.end(), {k1, d.k2, d.p1, d.p2});
  } else {
    c.model = "FULL_OPENCV";
    c.params.insert(c.params.end(), {k1, d.k2, d.p1, d.p2, d.k3, d.k4, d.k5, d.k6});
  }
  return c;
}

ColmapImage colmapImageOf(const OpenCvPose& pose, std::uint32_t id, std::uint32_t cameraId, std::string name,
                          const std::string& where) {
  if (name.empty()) throw InputError(cat(where, ": the image name is empty, which COLMAP's text format cannot hold"));
  if (name.find_first_of(" \t\r\n") != std::string::npos)
    throw InputError(cat(where, ": the image name ", name,
                         " holds a space, which COLMAP's text format cannot hold (it "
                         "reads NAME up to the first)"));
  ColmapImage image;
  image.id = id;
  image.rotation = quaternionFromRotation(pose.rows);
  image.translation = pose.translation;
  image.cameraId = cameraId;
  image.name = std::move(name);
  return image;
}

std::string colmapCamerasHeader() {
  return "# Camera list with one line of data per camera:\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n";
}

std::string colmapCameraLine(const ColmapCamera& c) {
  std::string text = cat(c.id, " ", c.model, " ", c.widthPx, " ", c.heightPx);
  for (const double p : c.params) {
    text += ' ';
    text += shortest(p);
  }
  text += "\n";
  return text;
}

std::string colmapCamerasFooter(std::size_t count) { return cat("# Number of cameras: ", count, "\n"); }

std::string colmapImagesHeader(std::size_t count) {
  return cat("# Image list with two lines of data per image:\n",
             "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n", "#   POINTS2D[] as (X, Y, POINT3D_ID)\n",
             "# Number of images: ", count, ", mean observations per image: 0\n");
}

std::string colmapImageLines(const ColmapImage& i) {
  const glm::dquat& q = i.rotation;
  return cat(i.id, " ", shortest(q.w), " ", shortest(q.x), " ", shortest(q.y), " ", shortest(q.z), " ",
             shortest(i.translation.x), " ", shortest(i.translation.y), " ", shortest(i.translation.z), " ", i.cameraId,
             " ", i.name, "\n\n");  // and its POINTS2D line, empty
}

std::string colmapCamerasText(const std::vector<ColmapCamera>& cameras) {
  std::string text = colmapCamerasHeader();
  for (const ColmapCamera& c : cameras) text += colmapCameraLine(c);
  return text + colmapCamerasFooter(cameras.size());
}

std::string colmapImagesText(const std::vector<ColmapImage>& images) {
  std::string text = colmapImagesHeader(images.size());
  for (const ColmapImage& i : images) text += colmapImageLines(i);
  return text;
}

std::string colmapPoints3DText() {
  return "# 3D point list with one line of data per point:\n"
         "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
         "# Number of points: 0, mean track length: 0\n";
}

}  // namespace lenslab
