#include "app/AovOption.h"

#include "core/Aovs.h"

namespace lenslab {

void addAovOptions(CLI::App& command, AovRequest& request) {
  command
      .add_option("--aov", request.names,
                  "ground truth beside the image (a list, e.g. depth,normal): depth = the distance from the lens "
                  "centre along the optical axis (world units, +inf where nothing is hit); normal = the shading "
                  "normal in camera space (--normal-convention); albedo = the linear base colour; instance = the "
                  "glTF node hit; flow (capture) = each pixel's motion to the next frame in pixels. One ray per pixel "
                  "centre from the lens centre (docs/capture.md)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(aovNames()))
      ->type_name("LIST");
  command
      .add_option("--aov-format", request.format,
                  "exr: channels of the image's EXR (Z, N.X N.Y N.Z, albedo.R ..., instance = node index), or of "
                  "IMAGE.aov.exr beside a PNG; npy: IMAGE.depth.npy float32 metres, IMAGE.normal.npy, "
                  "IMAGE.albedo.npy, IMAGE.instance.npy int32; png16: 16-bit PNGs, depth in millimetres (0 = "
                  "nothing hit); npy and png16 instance ids are node index + 1, named in instances.json")
      ->check(CLI::IsMember({"exr", "npy", "png16"}))
      ->capture_default_str();
  command
      .add_option("--normal-convention", request.normals,
                  "the normal AOV's camera frame: gl (x right, y up, z toward the viewer) or opencv (x right, y "
                  "down, z forward)")
      ->check(CLI::IsMember({"gl", "opencv"}))
      ->capture_default_str();
}

}  // namespace lenslab
