#pragma once
// --colmap DIR --image NAME: the camera of one photograph of a COLMAP text model (io/ColmapModel.h)
// as the base camera of render, raycast and view, instead of a camera file or the scene's camera.
#include "camera/PhysicalCamera.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace lenslab {

struct ColmapChoice {
  std::string dir;    // --colmap: the model's folder (cameras.txt, images.txt)
  std::string image;  // --image: the image's NAME in images.txt
};

void addColmapOptions(CLI::App& command, ColmapChoice& choice);

// The chosen image's camera, or nothing when neither option is given. Throws InputError for one
// option without the other, or for --colmap beside a camera file (`cameraFile` non-empty).
std::optional<SelectedCamera> selectColmapCamera(const ColmapChoice& choice, const std::string& cameraFile);

}  // namespace lenslab
