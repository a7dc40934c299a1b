#include "app/ColmapOptions.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/ColmapModel.h"

namespace lenslab {

void addColmapOptions(CLI::App& command, ColmapChoice& choice) {
  command.add_option("--colmap", choice.dir,
                     "a COLMAP text model's folder (cameras.txt, images.txt): render the view of the photograph --image "
                     "names, with its camera's intrinsics and distortion (docs/camera-files.md)")
      ->type_name("DIR");
  command.add_option("--image", choice.image, "with --colmap: the photograph's NAME in images.txt")->type_name("NAME");
}

std::optional<SelectedCamera> selectColmapCamera(const ColmapChoice& choice, const std::string& cameraFile) {
  if (choice.dir.empty() && choice.image.empty()) return std::nullopt;
  if (choice.image.empty())
    throw InputError(cat("--colmap ", choice.dir, ": give --image NAME too, the photograph whose view to render"));
  if (choice.dir.empty())
    throw InputError(cat("--image ", choice.image, ": give --colmap DIR too, the COLMAP model the image belongs to"));
  if (!cameraFile.empty())
    throw InputError(cat("--colmap ", choice.dir, " and --camera ", cameraFile, " both give the camera; give one"));
  return SelectedCamera{colmapImageCamera(readColmapModel(choice.dir), choice.image), std::nullopt};
}

}  // namespace lenslab
