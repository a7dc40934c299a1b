// The camera file's OpenCV form posed by R and t (X_cam = R·X_world + t) with K as a matrix or
// "intrinsics": world points land where OpenCV's projection K(R·X + t), written out in
// tests/common/opencv_model.h, puts them (plus OpenCV's half pixel); and each malformed key is
// refused in one line naming it.
#include "camera/ImageSize.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"

#include "../common/lenslab_pixel.h"
#include "../common/opencv_model.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace lenslab {
namespace {

using Matrix = std::array<glm::dvec3, 3>;  // row by row

// Rodrigues' formula: the rotation by `angle` about the unit `axis`,
// R = cos θ I + (1 − cos θ) k kᵀ + sin θ [k]×.
Matrix rodrigues(glm::dvec3 k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), C = 1 - c;
  return {glm::dvec3(c + C * k.x * k.x, C * k.x * k.y - s * k.z, C * k.x * k.z + s * k.y),
          glm::dvec3(C * k.y * k.x + s * k.z, c + C * k.y * k.y, C * k.y * k.z - s * k.x),
          glm::dvec3(C * k.z * k.x - s * k.y, C * k.z * k.y + s * k.x, c + C * k.z * k.z)};
}

glm::dvec3 times(const Matrix& r, const glm::dvec3& p) {
  return {glm::dot(r[0], p), glm::dot(r[1], p), glm::dot(r[2], p)};
}
glm::dvec3 transposedTimes(const Matrix& r, const glm::dvec3& p) { return p.x * r[0] + p.y * r[1] + p.z * r[2]; }

std::string json17(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}
// "[a, b, c]" (built with +=: GCC 12 warns, wrongly, on "[" + std::string).
std::string list(std::initializer_list<std::string> items) {
  std::string s = "[";
  for (const std::string& item : items) {
    if (s.size() > 1) s += ", ";
    s += item;
  }
  s += "]";
  return s;
}
std::string json17(const glm::dvec3& v) { return list({json17(v.x), json17(v.y), json17(v.z)}); }
std::string json17(const Matrix& m) { return list({json17(m[0]), json17(m[1]), json17(m[2])}); }

std::string kJson(const test::OpenCvCamera& c) {
  return list({list({json17(c.fx), "0", json17(c.cx)}), list({"0", json17(c.fy), json17(c.cy)}), "[0, 0, 1]"});
}
std::string distJson(const test::OpenCvCamera& c) {
  if (!c.beyondFive()) return list({json17(c.k1), json17(c.k2), json17(c.p1), json17(c.p2), json17(c.k3)});
  return list({json17(c.k1), json17(c.k2), json17(c.p1), json17(c.p2), json17(c.k3), json17(c.k4), json17(c.k5),
               json17(c.k6), json17(c.s1), json17(c.s2), json17(c.s3), json17(c.s4)});
}

const test::OpenCvCamera kLenses[] = {
    {520, 515, 330.2, 236.7},                                       // a pinhole
    {505, 512, 325.0, 230.0, -0.21, 0.06, 0.0021, -0.0013, -0.01},  // barrel, tangential, k3
    {530, 530, 319.5, 239.5, 0.15, 0.02},                           // pincushion
    // OpenCV's rational model and thin prism, all 12 coefficients
    {498, 503, 321.0, 242.0, -0.35, 0.12, 0.0015, -0.0011, 0.015, 0.09, 0.03, 0.004, 0.0012, -0.0007, 0.0009, 0.0003},
};

// Random poses, each lens, K and "intrinsics" alike: lenslab's pixel = OpenCV's + 0.5.
TEST(OpenCvPoseForm, PutsWorldPointsWhereKRXPlusTDoes) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const test::OpenCvCamera& cv : kLenses) {
    for (int pose = 0; pose < 6; ++pose) {
      const Matrix r =
          rodrigues(glm::normalize(glm::dvec3(uniform(rng), uniform(rng), uniform(rng))), M_PI * uniform(rng));
      const glm::dvec3 t = 5.0 * glm::dvec3(uniform(rng), uniform(rng), uniform(rng));
      const std::string poseKeys = ", \"R\": " + json17(r) + ", \"t\": " + json17(t) + ", \"dist\": " + distJson(cv);
      const std::string withK = "{\"K\": " + kJson(cv) + ", \"width\": 640, \"height\": 480" + poseKeys + "}";
      const std::string withIntrinsics = "{\"intrinsics\": {\"fx\": " + json17(cv.fx) + ", \"fy\": " + json17(cv.fy) +
                                         ", \"cx\": " + json17(cv.cx) + ", \"cy\": " + json17(cv.cy) +
                                         ", \"width\": 640, \"height\": 480}" + poseKeys + "}";
      for (const std::string& text : {withK, withIntrinsics}) {
        const Camera camera = parseCameraJson(text, "opencv.json").camera;
        const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
        ASSERT_EQ(size.widthPx, 640);
        ASSERT_EQ(size.heightPx, 480);
        EXPECT_TRUE(camera.lens.isPinhole());
        EXPECT_TRUE(camera.nearFromScene && camera.farFromScene);
        for (int i = 0; i < 300; ++i) {
          const double z = 0.2 * std::pow(100.0, 0.5 * (uniform(rng) + 1.0));
          const glm::dvec3 cam(0.55 * uniform(rng) * z, 0.42 * uniform(rng) * z, z);  // inside the image
          const glm::dvec3 world = transposedTimes(r, cam - t);                       // X = Rᵀ(X_cam − t)
          const glm::dvec2 opencv = cv.project(times(r, world) + t);                  // K(R·X + t), distorted
          const glm::dvec2 expected = opencv + glm::dvec2(0.5);  // lenslab's pixel centres are at i + 0.5
          const glm::dvec2 actual = test::lenslabPixel(camera, world, size);
          ASSERT_NEAR(actual.x, expected.x, 1e-6) << text;
          ASSERT_NEAR(actual.y, expected.y, 1e-6) << text;
        }
      }
    }
  }
}

TEST(OpenCvPoseForm, FocusAndApertureMoveTheFocusNotThePixels) {
  const test::OpenCvCamera cv = kLenses[1];
  const Matrix r = rodrigues(glm::normalize(glm::dvec3(0.3, -1.0, 0.2)), 0.7);
  const glm::dvec3 t(0.4, -0.2, 2.0);
  const std::string base = "{\"K\": " + kJson(cv) + ", \"image_size\": [640, 480], \"R\": " + json17(r) +
                           ", \"t\": " + json17(t) + ", \"dist\": " + distJson(cv);
  const Camera pinhole = parseCameraJson(base + "}", "p.json").camera;
  const Camera lens = parseCameraJson(base + ", \"focus_distance\": 3.5, \"aperture_radius\": 0.01}", "l.json").camera;
  const Camera far =
      parseCameraJson(base + ", \"focus_distance\": \"infinity\", \"aperture_radius\": 0.01}", "f.json").camera;
  EXPECT_NEAR(lens.focusDistance(), 3.5, 1e-12);
  EXPECT_EQ(lens.lens.apertureRadius, 0.01);
  EXPECT_TRUE(far.focusAtInfinity());
  const ImageSize size{640, 480};
  for (const glm::dvec3 cam : {glm::dvec3(0.1, 0.2, 1.0), glm::dvec3(-1.0, 0.5, 4.0), glm::dvec3(3.0, -2.0, 9.0)}) {
    const glm::dvec3 world = transposedTimes(r, cam - t);
    const glm::dvec2 expected = cv.project(cam) + glm::dvec2(0.5);
    for (const Camera* c : {&pinhole, &lens, &far}) {
      const glm::dvec2 actual = test::lenslabPixel(*c, world, size);
      EXPECT_NEAR(actual.x, expected.x, 1e-9);
      EXPECT_NEAR(actual.y, expected.y, 1e-9);
    }
  }
}

std::string errorOf(const std::string& text) {
  try {
    parseCameraJson(text, "cam.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

void expectHas(const std::string& message, std::initializer_list<const char*> parts) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;  // one line
  EXPECT_EQ(message.rfind("cam.json: ", 0), 0u) << message;     // naming the file first
  for (const char* part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(OpenCvPoseForm, EachBadKeyIsRefusedInOneLineNamingIt) {
  const std::string k = R"("K": [[500, 0, 320], [0, 500, 240], [0, 0, 1]], "width": 640, "height": 480)";
  const std::string rt = R"("R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [0, 0, 5])";
  const auto file = [](const std::string& body) { return "{" + body + "}"; };
  EXPECT_NO_THROW(parseCameraJson(file(k + ", " + rt), "cam.json"));
  expectHas(errorOf(file(R"("K": [[500, 0.5, 320], [0, 500, 240], [0, 0, 1]], "width": 640, "height": 480, )" + rt)),
            {"\"K\"", "skew", "0.5", "give 0"});
  expectHas(errorOf(file(R"("K": [[500, 0, 320], [2, 500, 240], [0, 0, 1]], "width": 640, "height": 480, )" + rt)),
            {"\"K\"", "K[1][0]"});
  expectHas(errorOf(file(R"("K": [[500, 0, 320], [0, 500, 240], [0, 0, 2]], "width": 640, "height": 480, )" + rt)),
            {"\"K\"", "[0, 0, 1]"});
  expectHas(errorOf(file(R"("K": [[500, 0, 320], [0, 500, 240]], "width": 640, "height": 480, )" + rt)),
            {"\"K\"", "3×3"});
  expectHas(errorOf(file(R"("K": [[-500, 0, 320], [0, 500, 240], [0, 0, 1]], "width": 640, "height": 480, )" + rt)),
            {"\"K\"", "focal length"});
  expectHas(errorOf(file(R"("K": [[500, 0, 320], [0, 500, 240], [0, 0, 1]], )" + rt)),
            {"\"K\"", "width", "image_size"});
  expectHas(errorOf(file(R"("K": [[500, 0, 320], [0, 500, 240], [0, 0, 1]], "width": 640, )" + rt)),
            {"\"height\" is missing"});
  expectHas(
      errorOf(file(k + R"(, "intrinsics": {"fx": 1, "fy": 1, "cx": 0, "cy": 0, "width": 2, "height": 2}, )" + rt)),
      {"\"K\"", "\"intrinsics\"", "give one"});
  // R: scaled, a reflection, four digits (refused), eight digits (accepted).
  expectHas(errorOf(file(k + R"(, "R": [[1.001, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [0, 0, 5])")),
            {"\"R\"", "not a rotation", "1e-06"});
  expectHas(errorOf(file(k + R"(, "R": [[-1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [0, 0, 5])")),
            {"\"R\"", "reflection", "det R"});
  expectHas(errorOf(file(k + R"(, "R": [[0.7071, -0.7071, 0], [0.7071, 0.7071, 0], [0, 0, 1]], "t": [0, 0, 5])")),
            {"\"R\"", "7 significant digits"});
  EXPECT_NO_THROW(parseCameraJson(
      file(k + R"(, "R": [[0.70710678, -0.70710678, 0], [0.70710678, 0.70710678, 0], [0, 0, 1]], "t": [0, 0, 5])"),
      "cam.json"));
  expectHas(errorOf(file(k + R"(, "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]])")), {"\"t\" is missing"});
  expectHas(errorOf(file(k + R"(, "t": [1, 2, 3])")), {"\"R\" is missing"});
  expectHas(errorOf(file(k + R"(, "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [0, 0, "5"])")), {"\"t\""});
  expectHas(errorOf(file(k + ", " + rt + R"(, "eye": [0, 0, 0], "target": [0, 0, -1])")),
            {"\"R\"", "eye", "give R and t"});
  expectHas(errorOf(file(k)), {"pose", "\"R\" and \"t\"", "\"eye\""});
  expectHas(errorOf(file(rt + R"(, "dist": [0, 0, 0, 0])")), {"intrinsics", "\"K\""});
  expectHas(errorOf(file(k + ", " + rt + R"(, "aperture_radius": 0.01)")), {"\"aperture_radius\"", "focus_distance"});
  expectHas(errorOf(file(k + ", " + rt + R"(, "dist": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.1, 0])")),
            {"\"dist\"", "tauX = 0.1", "tilted sensor"});
  expectHas(errorOf(file(k + ", " + rt + R"(, "dist": [0, 0, 0])")), {"\"dist\"", "4, 5, 8, 12 or 14 numbers"});
  expectHas(errorOf(file(k + ", " + rt + R"(, "dist": [0, 0, 0, 0], "distortion": {"k1": 0.1})")),
            {"\"dist\"", "give one"});
  expectHas(errorOf(file(k + ", " + rt + R"(, "vrp": [0, 0, 0])")), {"unknown key \"vrp\"", "OpenCV camera"});
  expectHas(
      errorOf(
          R"({"intrinsics": {"fx": 500, "fy": 500, "cx": 320, "cy": 240, "width": 640, "height": 480}, "width": 640, )" +
          rt + "}"),
      {"\"width\"", "inside \"intrinsics\""});
  // OpenCV's longer distCoeffs are read when what lenslab lacks is zero.
  const Camera c =
      parseCameraJson(file(k + ", " + rt + R"(, "dist": [-0.1, 0.01, 0, 0, 0.001, 0, 0, 0, 0, 0, 0, 0, 0, 0])"),
                      "cam.json")
          .camera;
  EXPECT_EQ(c.lens.effects.distortion.k1, -0.1);
  EXPECT_EQ(c.lens.effects.distortion.k3, 0.001);
}

}  // namespace
}  // namespace lenslab
