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
// The text files a line (cameras) or two (images) at a time, for a model written as it is made:
// cameras.txt is its header, a line per camera and a footer with the count (a comment, which
// COLMAP's readers skip wherever it is: the count is known only at the end); images.txt's header
// holds the count, known before the first image.
std::string colmapCamerasHeader();
std::string colmapCameraLine(const ColmapCamera& camera);
std::string colmapCamerasFooter(std::size_t count);
std::string colmapImagesHeader(std::size_t count);
std::string colmapImageLines(const ColmapImage& image);
// Whole files: the header, the lines, the footer.
std::string colmapCamerasText(const std::vector<ColmapCamera>& cameras);
std::string colmapImagesText(const std::vector<ColmapImage>& images);
std::string colmapPoints3DText();  // no points: the poses are known, a tool triangulates them

}  // namespace lenslab
