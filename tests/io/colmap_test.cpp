// COLMAP's text model: each camera model lenslab renders puts world points where COLMAP's own
// formulas (written out below from src/colmap/sensor/models.h and the "Output Format" page, not
// taken from lenslab) put them; the parser's refusals, each naming the file, the line and what
// would be valid; and a model written by lenslab reads back as the same cameras.
#include "camera/ImageSize.h"
#include "camera/Rotation.h"
#include "core/Error.h"
#include "io/ColmapExport.h"

#include "../common/lenslab_pixel.h"
#include "../common/refusal.h"
#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace lenslab {
namespace {

// --- COLMAP, written out -------------------------------------------------------------------

// A quaternion (w, x, y, z), Hamilton convention (i² = j² = k² = ijk = −1), as images.txt writes it.
struct Quat {
  double w, x, y, z;
};

Quat multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// Rotates p by the unit quaternion q: q (0, p) q*, the Hamilton product (no rotation matrix).
glm::dvec3 rotate(const Quat& q, const glm::dvec3& p) {
  const Quat r = multiply(multiply(q, {0.0, p.x, p.y, p.z}), {q.w, -q.x, -q.y, -q.z});
  return {r.x, r.y, r.z};
}

// COLMAP's ImgFromCam for each model, in its parameter order: normalised u = X/Z, v = Y/Z, the
// model's distortion (du, dv), then x = fx·(u + du) + cx. COLMAP's pixel coordinates put the
// image's top-left corner at (0, 0) and the centre of the top-left pixel at (0.5, 0.5).
glm::dvec2 colmapImgFromCam(const std::string& model, const std::vector<double>& p, const glm::dvec3& cam) {
  const double u = cam.x / cam.z, v = cam.y / cam.z;
  const double r2 = u * u + v * v;
  double fx = 0, fy = 0, cx = 0, cy = 0, du = 0, dv = 0;
  if (model == "SIMPLE_RADIAL_FISHEYE" || model == "RADIAL_FISHEYE" || model == "OPENCV_FISHEYE") {
    // The fisheyes: θ = atan r, θ_d = θ(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸), (u, v)·θ_d / r.
    const bool one = model != "OPENCV_FISHEYE";
    fx = p[0], fy = one ? p[0] : p[1], cx = p[one ? 1 : 2], cy = p[one ? 2 : 3];
    const std::size_t first = one ? 3 : 4;
    double k[4] = {0, 0, 0, 0};
    for (std::size_t i = first; i < p.size(); ++i) k[i - first] = p[i];
    const double r = std::sqrt(r2), theta = std::atan(r), t2 = theta * theta;
    const double thetaD = theta * (1 + k[0] * t2 + k[1] * t2 * t2 + k[2] * t2 * t2 * t2 + k[3] * t2 * t2 * t2 * t2);
    const double scale = r > 0 ? thetaD / r : 1.0;
    du = u * scale - u, dv = v * scale - v;
  } else if (model == "SIMPLE_PINHOLE" || model == "SIMPLE_RADIAL" || model == "RADIAL") {
    fx = fy = p[0], cx = p[1], cy = p[2];
    const double radial = model == "SIMPLE_PINHOLE"  ? 0.0
                          : model == "SIMPLE_RADIAL" ? p[3] * r2
                                                     : p[3] * r2 + p[4] * r2 * r2;
    du = u * radial, dv = v * radial;
  } else {
    fx = p[0], fy = p[1], cx = p[2], cy = p[3];
    if (model == "OPENCV") {
      const double k1 = p[4], k2 = p[5], p1 = p[6], p2 = p[7];
      const double radial = k1 * r2 + k2 * r2 * r2;
      du = u * radial + 2 * p1 * u * v + p2 * (r2 + 2 * u * u);
      dv = v * radial + 2 * p2 * u * v + p1 * (r2 + 2 * v * v);
    } else if (model == "FULL_OPENCV") {
      const double k1 = p[4], k2 = p[5], p1 = p[6], p2 = p[7], k3 = p[8], k4 = p[9], k5 = p[10], k6 = p[11];
      const double radial =
          (1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2) / (1 + k4 * r2 + k5 * r2 * r2 + k6 * r2 * r2 * r2);
      du = u * radial + 2 * p1 * u * v + p2 * (r2 + 2 * u * u) - u;
      dv = v * radial + 2 * p2 * u * v + p1 * (r2 + 2 * v * v) - v;
    }
  }
  return {fx * (u + du) + cx, fy * (v + dv) + cy};
}

std::string number(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

struct ModelCase {
  std::string model;
  std::vector<double> params;
};

const ModelCase kCases[] = {
    {"SIMPLE_PINHOLE", {812.5, 640.3, 360.8}},
    {"PINHOLE", {805.0, 798.5, 630.2, 365.9}},
    {"SIMPLE_RADIAL", {790.0, 641.0, 359.0, -0.12}},
    {"RADIAL", {795.0, 638.5, 362.5, -0.18, 0.04}},
    {"OPENCV", {801.0, 806.0, 645.5, 355.25, -0.21, 0.05, 0.0012, -0.0008}},
    {"FULL_OPENCV", {799.0, 803.0, 636.0, 361.0, -0.2, 0.045, -0.001, 0.0015, -0.008, 0.0, 0.0, 0.0}},
    {"FULL_OPENCV", {799.0, 803.0, 636.0, 361.0, -0.32, 0.11, -0.001, 0.0015, 0.012, 0.08, 0.025, 0.003}},
    {"SIMPLE_RADIAL_FISHEYE", {610.0, 641.0, 359.0, 0.021}},
    {"RADIAL_FISHEYE", {605.0, 638.5, 362.5, -0.015, 0.004}},
    {"OPENCV_FISHEYE", {601.0, 606.0, 645.5, 355.25, 0.012, -0.006, 0.0021, -0.0004}},
};

void PrintTo(const ModelCase& c, std::ostream* out) { *out << c.model; }

class ColmapCameraModel : public ::testing::TestWithParam<ModelCase> {};

TEST_P(ColmapCameraModel, PutsWorldPointsWhereColmapDoes) {
  const ModelCase& c = GetParam();
  constexpr int kWidth = 1280, kHeight = 720;
  std::string cameras = "# Camera list with one line of data per camera:\n7 " + c.model + " 1280 720";
  for (const double p : c.params) cameras += " " + number(p);
  cameras += "\n";
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int pose = 0; pose < 5; ++pose) {
    Quat q{gauss(rng), gauss(rng), gauss(rng), gauss(rng)};
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    q = {q.w / n, q.x / n, q.y / n, q.z / n};
    const glm::dvec3 t(3 * uniform(rng), 3 * uniform(rng), 3 * uniform(rng));
    const std::string images = "1 " + number(q.w) + " " + number(q.x) + " " + number(q.y) + " " + number(q.z) + " " +
                               number(t.x) + " " + number(t.y) + " " + number(t.z) + " 7 photo.jpg\n\n";
    ColmapModel model;
    model.cameras = parseColmapCameras(cameras, "cameras.txt");
    model.images = parseColmapImages(images, "images.txt");
    const Camera camera = colmapImageCamera(model, "photo.jpg");
    const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
    ASSERT_EQ(size.widthPx, kWidth);
    ASSERT_EQ(size.heightPx, kHeight);
    for (int i = 0; i < 500; ++i) {
      // A point in view: normalised coordinates inside the image (±0.75 by ±0.42 at these focal
      // lengths, where none of the distortions folds), at a depth of 0.3 to 30.
      const double z = 0.3 * std::pow(100.0, 0.5 * (uniform(rng) + 1.0));
      const glm::dvec3 cam(0.75 * uniform(rng) * z, 0.42 * uniform(rng) * z, z);
      const glm::dvec3 world = rotate({q.w, -q.x, -q.y, -q.z}, cam - t);  // X = R⁻¹(X_cam − t)
      // COLMAP: X_cam = R(q)·X + t, then the model.
      const glm::dvec2 colmapPixel = colmapImgFromCam(c.model, c.params, rotate(q, world) + t);
      // COLMAP's and lenslab's pixel coordinates are the same (top-left corner (0, 0), pixel
      // centres at i + 0.5): no shift. (OpenCV's would be colmapPixel − 0.5.)
      const glm::dvec2 expected = colmapPixel;
      const glm::dvec2 actual = test::lenslabPixel(camera, world, size);
      ASSERT_NEAR(actual.x, expected.x, 1e-6) << c.model << " pose " << pose << " point " << i;
      ASSERT_NEAR(actual.y, expected.y, 1e-6) << c.model << " pose " << pose << " point " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Models, ColmapCameraModel, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<ModelCase>& param) {
                           return param.param.model + "_" + std::to_string(param.index);
                         });

// --- reading: the layout -------------------------------------------------------------------

TEST(ColmapText, CommentsBlankLinesCarriageReturnsAndPointLinesAreRead) {
  const std::string cameras =
      "# header\r\n\r\n  1 PINHOLE 640 480 500 500 320 240\r\n\n\t# another\n2\tSIMPLE_PINHOLE  100 50 90 50 25\n";
  const std::vector<ColmapCamera> c = parseColmapCameras(cameras, "cameras.txt");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].line, 3);
  EXPECT_EQ(c[1].model, "SIMPLE_PINHOLE");
  EXPECT_EQ(c[1].params, (std::vector<double>{90, 50, 25}));
  // Two lines an image: an empty POINTS2D line, one with triples, and the last one missing at
  // the end of the file (COLMAP stops there too). A blank line after the POINTS2D line is skipped.
  const std::string images =
      "# Image list\n1 1 0 0 0 0 0 0 1 a.png\n\n\n2 1 0 0 0 1 2 3 2 b.png\n10.5 20.5 -1 30 40 7\n# c\n3 1 0 0 0 0 0 0 "
      "1 c.png";
  const std::vector<ColmapImage> i = parseColmapImages(images, "images.txt");
  ASSERT_EQ(i.size(), 3u);
  EXPECT_EQ(i[1].name, "b.png");
  EXPECT_EQ(i[1].translation, glm::dvec3(1, 2, 3));
  EXPECT_EQ(i[2].line, 8);
}

TEST(ColmapText, QuaternionsNearUnitLengthAreNormalisedAndOthersRefused) {
  // Six digits, as COLMAP's documentation prints them: within 1e-6 of unit length.
  const auto q = parseColmapImages("1 0.851773 0.0165051 0.503764 -0.142941 0 0 0 1 P.JPG\n\n", "i.txt")[0].rotation;
  EXPECT_NEAR(glm::length(q), 1.0, 1e-15);
  EXPECT_NEAR(q.w, 0.851773, 1e-6);
  // 2·(0.5, 0.5, 0.5, 0.5): the right rotation, but not what a COLMAP file holds.
  try {
    parseColmapImages("# x\n1 1 1 1 1 0 0 0 1 P.JPG\n", "sparse/images.txt");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sparse/images.txt:2:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("length 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseColmapImages("1 0 0 0 0 0 0 0 1 P.JPG\n", "i.txt"), InputError);
}

// The message of the InputError that `f` throws (and a failure when it throws none).
template <class F>
std::string errorOf(F f) {
  const std::string message = test::refusalOf(f);
  EXPECT_NE(message, "accepted") << "no InputError";
  return message;
}

void expectHas(const std::string& message, std::initializer_list<const char*> parts) {
  for (const char* part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(ColmapText, EachBadLineIsRefusedNamingFileLineAndField) {
  const auto cameras = [](const std::string& text) {
    return errorOf([&] { parseColmapCameras(text, "m/cameras.txt"); });
  };
  const auto images = [](const std::string& text) { return errorOf([&] { parseColmapImages(text, "m/images.txt"); }); };
  expectHas(cameras("# c\n1 PINHOLE 640 480 500 500 320\n"),
            {"m/cameras.txt:2:", "PINHOLE", "4 parameters", "fx, fy, cx, cy"});
  expectHas(cameras("1 PINHOLE 640 480 500 five 320 240\n"), {"m/cameras.txt:1:", "parameter 2", "five"});
  expectHas(cameras("1 PINHOLE 640 480 500 nan 320 240\n"), {"m/cameras.txt:1:", "finite"});
  expectHas(cameras("1 PINHOLE 640 480 500 1e309 320 240\n"), {"m/cameras.txt:1:", "1e309 is not a finite number"});
  // A long field is quoted short (at most 60 characters and an ellipsis).
  const std::string longField = cameras("1 PINHOLE 640 480 500 " + std::string(100000, 'x') + " 320 240\n");
  expectHas(longField, {"m/cameras.txt:1:", "xxx…"});
  EXPECT_LT(longField.size(), 400u);
  expectHas(cameras("1 PINHOLE 640\n"), {"m/cameras.txt:1:", "CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]"});
  expectHas(cameras("1 PINHOLE 640 -480 500 500 320 240\n"), {"m/cameras.txt:1:", "HEIGHT"});
  expectHas(cameras("1 PINHOLE 640 0 500 500 320 240\n"), {"m/cameras.txt:1:", "at least 1x1"});
  expectHas(cameras("-1 PINHOLE 640 480 500 500 320 240\n"), {"m/cameras.txt:1:", "CAMERA_ID"});
  expectHas(cameras("1 PINHOLE 640 480 500 500 320 240\n\n1 PINHOLE 640 480 500 500 320 240\n"),
            {"m/cameras.txt:3:", "CAMERA_ID 1", "line 1"});
  expectHas(images("1 1 0 0 0 0 0 0 1 my photo.png\n\n"), {"m/images.txt:1:", "10 fields", "spaces"});
  expectHas(images("1 1 0 0 0 0 0 1 a.png\n\n"), {"m/images.txt:1:", "IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME"});
  expectHas(images("1 1 0 0 0 0 x 0 1 a.png\n\n"), {"m/images.txt:1:", "TY"});
  // A file without POINTS2D lines: the second image's line is read as the first's points.
  expectHas(images("1 1 0 0 0 0 0 0 1 a.png\n2 1 0 0 0 0 0 0 1 b.png\n"), {"m/images.txt:2:", "POINTS2D", "two lines"});
  expectHas(images("1 1 0 0 0 0 0 0 1 a.png\n# points\n"), {"m/images.txt:2:", "POINTS2D", "comment"});
  expectHas(images("1 1 0 0 0 0 0 0 1 a.png\n\n1 1 0 0 0 0 0 0 1 b.png\n\n"), {"m/images.txt:3:", "IMAGE_ID 1"});
  expectHas(images("1 1 0 0 0 0 0 0 1 a.png\n\n2 1 0 0 0 0 0 0 1 a.png\n\n"), {"m/images.txt:3:", "NAME a.png"});
}

TEST(ColmapText, ModelsLenslabDoesNotRenderAreRefusedByNameWhenUsed) {
  ColmapModel model;
  model.camerasFile = "m/cameras.txt";
  model.imagesFile = "m/images.txt";
  model.cameras = parseColmapCameras(
      "1 FOV 640 480 500 500 320 240 0.9\n2 PINHOLE 640 480 500 500 320 240\n"
      "3 FULL_OPENCV 640 480 500 500 320 240 0 0 0 0 0 0.1 0 0\n4 SIMPLE_PINHOLE 640 480 -5 320 240\n"
      "5 PINHOLE 70000 480 500 500 320 240\n6 PINHOLE 640 480 500 500 1e30 240\n",
      model.camerasFile);
  model.images = parseColmapImages(
      "1 1 0 0 0 0 0 0 1 fish.png\n\n2 1 0 0 0 0 0 0 2 pin.png\n\n3 1 0 0 0 0 0 0 3 full.png\n\n"
      "4 1 0 0 0 0 0 0 4 neg.png\n\n5 1 0 0 0 0 0 0 5 wide.png\n\n6 1 0 0 0 0 0 0 9 lost.png\n\n"
      "7 1 0 0 0 0 0 0 6 far.png\n\n",
      "m/images.txt");
  // Another image's camera is fine: the FOV model is refused only for its own image.
  EXPECT_NO_THROW(colmapImageCamera(model, "pin.png"));
  expectHas(errorOf([&] { colmapImageCamera(model, "fish.png"); }),
            {"m/cameras.txt:1:", "camera 1 is FOV", "SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV",
             "RADIAL_FISHEYE"});
  EXPECT_EQ(colmapImageCamera(model, "full.png").lens.effects.distortion.k4, 0.1);  // the rational model
  expectHas(errorOf([&] { colmapImageCamera(model, "neg.png"); }), {"m/cameras.txt:4:", "focal length -5"});
  expectHas(errorOf([&] { colmapImageCamera(model, "wide.png"); }), {"m/cameras.txt:5:", "65536"});
  expectHas(errorOf([&] { colmapImageCamera(model, "lost.png"); }), {"m/images.txt:11:", "CAMERA_ID 9"});
  // A principal point 1e30 pixels out is refused naming cx and its range (not as an empty window).
  expectHas(errorOf([&] { colmapImageCamera(model, "far.png"); }),
            {"m/cameras.txt:6:", "cx 1e+30", "within 100 image sides", "-63680 to 64320"});
  // An unknown name lists some that are there; a name without its folder finds it.
  expectHas(errorOf([&] { colmapImageCamera(model, "nothere.png"); }),
            {"--image nothere.png", "7 images", "fish.png, pin.png, full.png, neg.png, wide.png, ..."});
  model.images.push_back(model.images[1]);
  model.images.back().name = "left/cam0.png";
  expectHas(errorOf([&] { colmapImageCamera(model, "cam0.png"); }), {"did you mean left/cam0.png?"});
}

class ColmapFolder : public test::TempDirTest {
 protected:
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
};

TEST_F(ColmapFolder, ReadsTheTextModelAndTheBinaryOneFirstAsColmapDoes) {
  write("cameras.txt", "1 PINHOLE 64 48 50 50 32 24\n");
  write("images.txt", "1 1 0 0 0 0 0 5 1 frame.png\n\n2 1 0 0 0 0 0 5 3 other.png\n\n");
  expectHas(errorOf([&] { readColmapModel(dir_); }), {"images.txt:3:", "CAMERA_ID 3", "cameras.txt"});
  write("images.txt", "1 1 0 0 0 0 0 5 1 frame.png\n\n");
  const ColmapModel model = readColmapModel(dir_);
  EXPECT_EQ(model.images.size(), 1u);
  const Camera camera = colmapImageCamera(model, "frame.png");
  EXPECT_NE(camera.source.find("frame.png"), std::string::npos);
  expectHas(errorOf([&] { readColmapModel(dir_ / "missing"); }), {"missing", "not a folder"});
  // Both formats in one folder: COLMAP reads the binary one, and so does lenslab.
  write("cameras.bin", "binary");
  write("images.bin", "binary");
  expectHas(errorOf([&] { readColmapModel(dir_); }), {"cameras.bin", "ends inside the number of cameras"});
}

// --- writing --------------------------------------------------------------------------------

TEST(ColmapWrite, TheSimplestModelThatHoldsTheLensExactly) {
  const OpenCvIntrinsics k{800.0, 790.0, 319.5, 239.5, 640, 480};
  Distortion d;
  ColmapCamera c = colmapCameraOf(k, d, 1, "t");
  EXPECT_EQ(c.model, "PINHOLE");
  // OpenCV's principal point (centres on integers) + 0.5 = COLMAP's.
  EXPECT_EQ(c.params, (std::vector<double>{800.0, 790.0, 320.0, 240.0}));
  d.k1 = -0.1, d.p2 = 0.002, d.beta = 0.03;  // the lecture's β is the r² term, as k1 is
  c = colmapCameraOf(k, d, 1, "t");
  EXPECT_EQ(c.model, "OPENCV");
  EXPECT_EQ(c.params, (std::vector<double>{800.0, 790.0, 320.0, 240.0, -0.1 + 0.03, 0.0, 0.0, 0.002}));
  d.k3 = 0.01;
  c = colmapCameraOf(k, d, 1, "t");
  EXPECT_EQ(c.model, "FULL_OPENCV");
  EXPECT_EQ(c.params.size(), 12u);
  EXPECT_EQ(c.params[8], 0.01);
  d.k3 = 0.0, d.k5 = 0.004;  // the rational model alone needs FULL_OPENCV too
  c = colmapCameraOf(k, d, 1, "t");
  EXPECT_EQ(c.model, "FULL_OPENCV");
  EXPECT_EQ(c.params[10], 0.004);
  d.s3 = 0.001;  // OpenCV's thin prism: no COLMAP model
  expectHas(errorOf([&] { colmapCameraOf(k, d, 1, "path.json: frame 3"); }), {"path.json: frame 3", "s3 0.001"});
  d.s3 = 0.0;
  d.alpha = 0.02;
  expectHas(errorOf([&] { colmapCameraOf(k, d, 1, "path.json: frame 3"); }),
            {"path.json: frame 3", "alpha", "k1, k2, p1, p2, k3"});
  EXPECT_THROW(colmapImageOf({}, 1, 1, "two words.png", "t"), InputError);
}

TEST(ColmapWrite, AFisheyeIsOpenCvFisheyeAndReadsBackAsTheSameLens) {
  const OpenCvIntrinsics k{600.0, 602.0, 319.5, 239.5, 640, 480};
  Distortion d;
  d.fisheye = true;  // the equidistant fisheye: k1 … k4 = 0, but not a pinhole
  ColmapCamera c = colmapCameraOf(k, d, 1, "t");
  EXPECT_EQ(c.model, "OPENCV_FISHEYE");
  EXPECT_EQ(c.params, (std::vector<double>{600.0, 602.0, 320.0, 240.0, 0.0, 0.0, 0.0, 0.0}));
  d.k1 = 0.02, d.k2 = -0.004, d.k3 = 0.001, d.k4 = -0.0002;
  c = colmapCameraOf(k, d, 1, "t");
  EXPECT_EQ(c.params, (std::vector<double>{600.0, 602.0, 320.0, 240.0, 0.02, -0.004, 0.001, -0.0002}));
  const OpenCvLens back = lensOf(parseColmapCameras(colmapCamerasText({c}), "cameras.txt")[0], "cameras.txt");
  EXPECT_TRUE(back.distortion.fisheye);
  EXPECT_EQ(back.distortion.k3, 0.001);
  EXPECT_EQ(back.distortion.k4, -0.0002);
  EXPECT_EQ(back.distortion.p1, 0.0);  // θ's k3, k4 are not OpenCV's p1, p2
  EXPECT_EQ(back.intrinsics.cx, 319.5);
}

TEST(ColmapWrite, AWrittenModelReadsBackAsTheSameCameras) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<ColmapCamera> cameras;
  std::vector<ColmapImage> images;
  std::vector<OpenCvPose> poses;
  for (std::uint32_t i = 0; i < 40; ++i) {
    const OpenCvIntrinsics k{700.0 + 100 * uniform(rng),
                             700.0 + 100 * uniform(rng),
                             320 + 5 * uniform(rng),
                             240 + 5 * uniform(rng),
                             640,
                             480};
    Distortion d;
    if (i % 3 > 0)
      d.k1 = 0.2 * uniform(rng), d.k2 = 0.05 * uniform(rng), d.p1 = 1e-3 * uniform(rng), d.p2 = 1e-3 * uniform(rng);
    if (i % 3 > 1) d.k3 = 0.01 * uniform(rng);
    cameras.push_back(colmapCameraOf(k, d, i + 1, "t"));
    // Rotations all round, 180° about an axis included (where w = 0).
    const glm::dvec3 axis = glm::normalize(glm::dvec3(uniform(rng), uniform(rng), uniform(rng)));
    const double angle = i == 0 ? M_PI : M_PI * uniform(rng);
    const glm::dquat q{std::cos(angle / 2), axis.x * std::sin(angle / 2), axis.y * std::sin(angle / 2),
                       axis.z * std::sin(angle / 2)};
    OpenCvPose pose{rotationFromQuaternion(q), glm::dvec3(uniform(rng), uniform(rng), uniform(rng)) * 10.0};
    poses.push_back(pose);
    images.push_back(colmapImageOf(pose, 100 + i, i + 1, "frames/frame_" + std::to_string(i) + ".png", "t"));
  }
  const std::vector<ColmapCamera> camerasBack = parseColmapCameras(colmapCamerasText(cameras), "cameras.txt");
  const std::vector<ColmapImage> imagesBack = parseColmapImages(colmapImagesText(images), "images.txt");
  EXPECT_TRUE(parseColmapImages(colmapPoints3DText(), "points3D.txt").empty());  // comments only
  ASSERT_EQ(camerasBack.size(), cameras.size());
  ASSERT_EQ(imagesBack.size(), images.size());
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    EXPECT_EQ(camerasBack[i].id, cameras[i].id);
    EXPECT_EQ(camerasBack[i].model, cameras[i].model);
    EXPECT_EQ(camerasBack[i].widthPx, 640);
    ASSERT_EQ(camerasBack[i].params.size(), cameras[i].params.size());
    for (std::size_t p = 0; p < cameras[i].params.size(); ++p)
      EXPECT_NEAR(camerasBack[i].params[p], cameras[i].params[p], 1e-9 * std::max(1.0, std::abs(cameras[i].params[p])));
    EXPECT_EQ(imagesBack[i].name, images[i].name);
    EXPECT_EQ(imagesBack[i].cameraId, i + 1);
    const OpenCvPose back = poseOf(imagesBack[i]);
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col) EXPECT_NEAR(back.rows[r][col], poses[i].rows[r][col], 1e-9) << i;
    EXPECT_NEAR(glm::length(back.translation - poses[i].translation), 0.0, 1e-9);
  }
}

TEST(Rotation, QuaternionAndMatrixRoundTripAtEveryAngle) {
  std::mt19937 rng(9);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 2000; ++i) {
    glm::dquat q{gauss(rng), gauss(rng), gauss(rng), gauss(rng)};
    if (i % 4 == 0) q.w = 1e-9 * gauss(rng);  // near 180°
    const double n = glm::length(q);
    q = {q.w / n, q.x / n, q.y / n, q.z / n};
    const RotationRows r = rotationFromQuaternion(q);
    const RotationCheck check = checkRotation(r);
    EXPECT_LT(check.orthonormalityError, 1e-14);
    EXPECT_NEAR(check.determinant, 1.0, 1e-14);
    // The matrix rotates as the quaternion does (Hamilton product, written out above).
    const glm::dvec3 p(gauss(rng), gauss(rng), gauss(rng));
    const glm::dvec3 byQuat = rotate({q.w, q.x, q.y, q.z}, p);
    EXPECT_NEAR(glm::length(glm::dvec3(glm::dot(r[0], p), glm::dot(r[1], p), glm::dot(r[2], p)) - byQuat), 0.0, 1e-13);
    const glm::dquat back = quaternionFromRotation(r);
    const double sign = (back.w * q.w + back.x * q.x + back.y * q.y + back.z * q.z) < 0 ? -1.0 : 1.0;  // q ≡ −q
    EXPECT_NEAR(back.w, sign * q.w, 1e-12);
    EXPECT_NEAR(back.x, sign * q.x, 1e-12);
    EXPECT_NEAR(back.y, sign * q.y, 1e-12);
    EXPECT_NEAR(back.z, sign * q.z, 1e-12);
    EXPECT_GE(back.w, 0.0);
  }
}

}  // namespace
}  // namespace lenslab
