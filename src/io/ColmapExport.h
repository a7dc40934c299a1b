#pragma once
// COLMAP's sparse model written (capture --colmap-out): a lenslab camera's intrinsics and pose as
// COLMAP's camera and image lines, and the text of cameras.txt, images.txt and an empty
// points3D.txt. The conventions are io/ColmapModel.h's.
#include "io/ColmapModel.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {

// The simplest model that holds a lens exactly: PINHOLE without distortion, OPENCV for k1, k2,
// p1, p2, FULL_OPENCV (k4 = k5 = k6 = 0) when k3 ≠ 0; the lecture's β adds to k1. Throws
// InputError naming `where` for the lecture's odd powers α and γ, which no COLMAP model holds.
ColmapCamera colmapCameraOf(const OpenCvIntrinsics& k, const Distortion& distortion, std::uint32_t id,
                            const std::string& where);
// Throws InputError naming `where` for a name that is empty or holds white space.
ColmapImage colmapImageOf(const OpenCvPose& pose, std::uint32_t id, std::uint32_t cameraId, std::string name,
                          const std::string& where);

// The files' text, with COLMAP's header comments; numbers in the shortest form that reads back
// to the same double.
std::string colmapCamerasText(const std::vector<ColmapCamera>& cameras);
std::string colmapImagesText(const std::vector<ColmapImage>& images);
std::string colmapPoints3DText();  // no points: the poses are known, a tool triangulates them

}  // namespace lenslab
