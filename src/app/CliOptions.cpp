#include "app/CliOptions.h"

#include "core/Text.h"
#include "lens/AperturePattern.h"

#include <cmath>

namespace lenslab {

CLI::Validator numberIn(const NumberRange& range) {
  return CLI::Validator([range](std::string& text) { return numberTextProblem(text, range).value_or(std::string()); },
                        std::string());
}

CLI::Validator numberOrInfinity(const NumberRange& range) {
  return CLI::Validator(
      [range](std::string& text) {
        if (text == "infinity") return std::string();
        const std::optional<std::string> problem = numberTextProblem(text, range);
        return problem ? *problem + ", or infinity" : std::string();
      },
      std::string());
}

void addSamplingOptions(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--pattern", o.pattern,
                 "aperture pattern: " + patternNames() + " (default: sobol; see docs/sampling.md)")
      ->check(CLI::IsMember(patternNameList()));
  CLI::Option* samples =
      cmd.add_option(
             "--aperture-samples", o.apertureSamples,
             "scene passes, one per aperture point, each jittered within the pixel: a number, or auto (from the "
             "largest circle of confusion in view, and at least 16 for anti-aliasing, a pinhole's included); 1 "
             "draws one plain pass")
          ->check(CLI::IsMember({"auto"}) | CLI::Range(1, 65536))
          ->capture_default_str();
  CLI::Option* max = cmd.add_option("--max-samples", o.maxSamples,
                                    "the most aperture samples auto may choose (with --target-psnr: per tile)")
                         ->check(CLI::Range(1, 65536))
                         ->capture_default_str();
  cmd.add_option("--cell-filter", o.cellFilter,
                 "on: spread each view over its cell of the aperture at each pixel's depth: fewer views for the "
                 "same error, each view costing more (thin-lens frames without warping lens effects; see "
                 "docs/depth-of-field.md); off (default)")
      ->check(CLI::IsMember({"on", "off"}));
  // A fixed count leaves nothing for a cap to do: say so rather than ignore it.
  cmd.parse_complete_callback([samples, max, &o] {
    if (max->count() > 0 && samples->count() > 0 && o.apertureSamples != "auto")
      throw CLI::ValidationError("--max-samples",
                                 cat("caps the count that auto (or --target-psnr) chooses; --aperture-samples ",
                                     o.apertureSamples, " fixes it: give one or the other"));
  });
}

void addSeedOption(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--seed", o.seed, "seed for the aperture and sub-pixel samples")->capture_default_str();
}

void addFocusOptions(CLI::App& cmd, LensOptions& o) {
  CLI::Option* distance = cmd.add_option("--focus-distance", o.focusDistance,
                                         "put the plane of focus this far from the PRP (world units, or infinity)")
                              ->check(numberOrInfinity({.unit = "world units"}));
  // --focus-at sets the focus after --focus-distance would: one of the two.
  addPairOption(cmd, "--focus-at", [&o](double x, double y) { o.focusAt = glm::dvec2(x, y); },
                "focus on the depth under pixel X,Y of the image", {.unit = "pixels"})
      ->excludes(distance);
}

namespace {

void addLensEffectOptions(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--distortion", o.distortion,
                 "lens distortion as OpenCV's distCoeffs k1,k2,p1,p2,k3,k4,k5,k6,s1,s2,s3,s4 (1 to 12 numbers, the "
                 "missing ones 0; e.g. -0.2 for a barrel, 0.1 for a pincushion), over the camera file's \"distortion\"")
      ->check(numberIn({.min = -1e4, .max = 1e4, .unit = {}}))
      ->delimiter(',')
      ->expected(1, 64)  // more than 12 is refused with the terms named (withLensEffectOptions)
      ->type_name("K1[,K2,...]");
  cmd.add_option("--fisheye", o.fisheye,
                 "OpenCV's fisheye model over the camera file's \"distortion\": its k1,k2,k3,k4 (cv::fisheye's D; "
                 "1 to 4 numbers, the missing ones 0), theta_d = theta (1 + k1 theta^2 + ...); 0 for the equidistant "
                 "fisheye")
      ->check(numberIn({.min = -1e4, .max = 1e4, .unit = {}}))
      ->delimiter(',')
      ->expected(1, 64)  // more than 4 is refused with the terms named (withLensEffectOptions)
      ->excludes("--distortion")
      ->type_name("K1[,K2,K3,K4]");
  cmd.add_option("--lateral-color", o.lateralColor,
                 "lateral chromatic aberration: red's and blue's images magnified about the centre by this fraction "
                 "of green's (e.g. 0.002,-0.002; one number L: red L and blue -L), over the camera file's")
      ->check(numberIn({.min = -0.49, .max = 0.49, .unit = {}}))
      ->delimiter(',')
      ->expected(1, 64)
      ->type_name("RED[,BLUE]");
  cmd.add_option("--axial-color", o.axialAbbe,
                 "axial chromatic aberration of a simple lens of glass with this Abbe number (about 20 for dense "
                 "flint to 90 for fluorite; 60 is crown glass): red focused farther, blue nearer; needs a camera in "
                 "the physical form (its focal length)")
      ->check(numberIn({.min = 1.0, .max = 1000.0, .unit = {}}))
      ->type_name("ABBE");
}

}  // namespace

void addLensOverrideOptions(CLI::App& cmd, LensOptions& o) {
  addLensEffectOptions(cmd, o);
  cmd.add_option(
         "--blades", o.blades,
         "aperture blades: 0 for a round aperture, 3 to 64 for a polygon of the same area (out-of-focus highlights "
         "take its shape); over the camera file's \"aperture\"")
      ->type_name("N");
  cmd.add_option("--squeeze", o.squeeze,
                 "anamorphic squeeze: the aperture taller than wide by this ratio, e.g. 1.33 or 2 (1: none); over the "
                 "camera file's \"aperture\"")
      ->type_name("RATIO");
}

namespace {

// An option that takes a point as X,Y,Z (three finite numbers).
void addPointOption(CLI::App& cmd, const std::string& name, std::optional<glm::dvec3>& point,
                    const std::string& description) {
  cmd.add_option_function<std::vector<double>>(
         name, [&point](const std::vector<double>& xyz) { point = glm::dvec3(xyz[0], xyz[1], xyz[2]); }, description)
      ->check(numberIn({.unit = "world units"}))
      ->delimiter(',')
      ->expected(3)
      ->type_name("X,Y,Z");
}

}  // namespace

void addCameraNodeOption(CLI::App& cmd, CameraOptions& o) {
  cmd.add_option(
         "--camera-node", o.cameraNode,
         "use this glTF camera of the scene: its node's name, its camera's name, or its index (as `lenslab info` "
         "lists them; default: the first)")
      ->type_name("NAME|INDEX");
}

void addCameraOptions(CLI::App& cmd, CameraOptions& o, bool withPose, bool withAnimation) {
  cmd.add_option("--focal-length", o.focalLengthMm,
                 "lens focal length in mm, overriding the camera's (a new focal length changes the field of view)")
      ->check(numberIn({.min = 0.01, .max = 1e6, .unit = "millimetres"}))
      ->type_name("MM");
  cmd.add_option("--f-number", o.fNumber,
                 "aperture as an f-number N (radius f/2N), e.g. 2.8, for depth of field; infinity: a pinhole")
      ->type_name("N");
  cmd.add_option("--sensor", o.sensor, "sensor size: WxH in mm (e.g. 36x24), or " + namedSensorList())
      ->type_name("WxH|NAME");
  if (withPose) {
    addPointOption(cmd, "--eye", o.eye, "put the lens centre here (world units), overriding the camera's");
    addPointOption(cmd, "--target", o.target,
                   "look at this point (world units), overriding the camera's; a camera focused on its target stays "
                   "focused on it");
  }
  addCameraNodeOption(cmd, o);
  if (!withAnimation) return;
  cmd.add_option("--animation", o.animation,
                 "which glTF animation plays: its name, its index (as `lenslab info` lists them), or all (together); "
                 "default: the first")
      ->type_name("NAME|INDEX|all");
}

void addTargetOption(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--target-psnr", o.targetPsnrDb,
                 "render to an error instead of a count: each 32-px tile gets its own number of samples, in a "
                 "progressive order, until the estimated PSNR of the image against its own converged limit reaches DB "
                 "(--max-samples still caps each tile)")
      ->check(numberIn({.min = 10.0, .max = 100.0, .unit = "dB"}))
      ->type_name("DB");
}

void addTimeOption(CLI::App& cmd, std::optional<double>& seconds, const std::string& description) {
  cmd.add_option("--time", seconds, description)
      ->check(numberIn({.min = -1e9, .max = 1e9, .unit = "seconds"}))
      ->type_name("SECONDS");
}

CLI::Option* addPairOption(CLI::App& cmd, const std::string& name, std::function<void(double, double)> set,
                           const std::string& description, const NumberRange& range) {
  return cmd
      .add_option_function<std::vector<double>>(
          name, [set](const std::vector<double>& xy) { set(xy[0], xy[1]); }, description)
      ->check(numberIn(range))
      ->delimiter(',')
      ->expected(2)
      ->type_name("X,Y");
}

void addBackgroundOption(CLI::App& cmd, std::optional<glm::vec3>& background) {
  cmd.add_option_function<std::vector<double>>(
         "--background",
         [&background](const std::vector<double>& rgb) {
           background = glm::vec3(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]));
         },
         "colour where no surface is seen, linear R,G,B (e.g. 0,0,0); default: the scene's (a dark blue grey, "
         "0.05,0.06,0.08)")
      ->check(numberIn({.min = 0.0, .max = 65504.0, .unit = "linear values"}))
      ->delimiter(',')
      ->expected(3);
}

void addLensFileOptions(CLI::App& cmd, std::string& file, const std::string& description, double* tolerancePx) {
  cmd.add_option("--lens", file, description)->type_name("FILE");
  if (!tolerancePx) return;
  cmd.add_option("--lens-tolerance", *tolerancePx,
                 "with --lens: the largest error of the fitted lens, in pixels of this image, for the real-time path")
      ->check(numberIn({.min = 0.0, .max = 1e6, .unit = "pixels"}))
      ->type_name("PX")
      ->capture_default_str();
}

void addColmapOptions(CLI::App& cmd, CameraOptions& o) {
  cmd.add_option("--colmap", o.colmapDir,
                 "a COLMAP text model's folder (cameras.txt, images.txt): render the view of the photograph --image "
                 "names, with its camera's intrinsics and distortion (docs/camera-files.md)")
      ->type_name("DIR");
  cmd.add_option("--image", o.colmapImage, "with --colmap: the photograph's NAME in images.txt")->type_name("NAME");
}

}  // namespace lenslab
