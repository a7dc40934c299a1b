// lenslab.read_image and write_image: image files through the command line's own reader and writer
// (OpenImageIO; PNG 8-bit sRGB, EXR linear float, written whole or not at all), so that a frame
// written from Python is the file `lenslab render --out` writes of the same pixels.
#include "app/AovOutputs.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/ImageFile.h"
#include "python/Arrays.h"
#include "python/Bindings.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <iostream>
#include <optional>

namespace lenslab::python {
namespace py = pybind11;

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using IdArray = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

// An AOV array of `perPixel` values a pixel for an image of `width` × `height`, as a vector.
template <class T>
std::vector<float> aovValues(const py::array_t<T, py::array::c_style | py::array::forcecast>& a, int width, int height,
                             int perPixel, const char* name) {
  const bool shaped = perPixel == 1 ? a.ndim() == 2 : a.ndim() == 3 && a.shape(2) == perPixel;
  if (!shaped || a.shape(0) != height || a.shape(1) != width)
    throw InputError(cat("lenslab.write: the frame's ", name, " is not of shape (", height, ", ", width,
                         perPixel == 1 ? "" : cat(", ", perPixel), ")"));
  return std::vector<float>(a.data(), a.data() + a.size());
}

// A frame from Renderer.render as `lenslab render --out PATH --aov ... --aov-format F` writes it:
// the image and, beside it, the AOVs it holds (its normals already in the convention asked for),
// and for the instance AOV the ids' names; whole or not at all.
void writeFrame(const std::filesystem::path& path, const FloatArray& rgba, const std::optional<FloatArray>& depth,
                const std::optional<FloatArray>& normal, const std::optional<FloatArray>& albedo,
                const std::optional<IdArray>& instance, const std::string& aovFormat, const PyScene& scene) {
  AovRequest request;
  request.format = aovFormat;
  if (depth) request.names.push_back("depth");
  if (normal) request.names.push_back("normal");
  if (albedo) request.names.push_back("albedo");
  if (instance) request.names.push_back("instance");
  if (aovFormat != "exr" && aovFormat != "npy" && aovFormat != "png16")
    throw InputError(cat("aov_format \"", aovFormat, "\": give \"exr\", \"npy\" or \"png16\""));
  if (request.names.empty()) request.format = "exr";  // no AOVs: the format says nothing
  const AovOutput output = checkedAovOutput(request, path, "path");
  if (rgba.ndim() != 3 || rgba.shape(2) != 4)
    throw InputError(cat(path.string(), ": give the image as float RGBA of shape (height, width, 4)"));
  const int width = static_cast<int>(rgba.shape(1)), height = static_cast<int>(rgba.shape(0));
  Image image(width, height);
  std::copy(rgba.data(), rgba.data() + rgba.size(), image.rgba.begin());
  AovImages aovs;
  aovs.widthPx = width, aovs.heightPx = height;
  if (depth) aovs.depth = aovValues(*depth, width, height, 1, "depth");
  if (normal) aovs.normal = aovValues(*normal, width, height, 3, "normal");
  if (albedo) aovs.albedo = aovValues(*albedo, width, height, 3, "albedo");
  if (instance) aovs.instance = aovValues(*instance, width, height, 1, "instance");
  py::gil_scoped_release release;
  OutputSet outputs;
  const auto warn = [](const std::string& w) { std::cerr << "lenslab: warning: " << w << "\n"; };
  writeImage(outputs, path, image, addAovOutputs(outputs, path, aovs, output, *scene.scene, warn));
  outputs.commit();
}

}  // namespace

void bindFiles(py::module_& m) {
  m.def(
      "read_image",
      [](const std::filesystem::path& path) {
        Image image;
        {
          py::gil_scoped_release release;
          image = readImage(path);
        }
        return arrayOf(std::move(image.rgba), {image.height, image.width, 4});
      },
      py::arg("path"),
      "An image file as linear float32 RGBA, shape (height, width, 4), rows from the top (PNG decoded from sRGB).");
  m.def(
      "_write_image",
      [](const std::filesystem::path& path, const py::array_t<float, py::array::c_style | py::array::forcecast>& rgba) {
        checkImageExtension(path);
        if (rgba.ndim() != 3 || rgba.shape(2) != 4)
          throw InputError(cat(path.string(), ": give the image as float RGBA of shape (height, width, 4)"));
        Image image(static_cast<int>(rgba.shape(1)), static_cast<int>(rgba.shape(0)));
        std::copy(rgba.data(), rgba.data() + rgba.size(), image.rgba.begin());
        py::gil_scoped_release release;
        writeImage(path, image);
      },
      py::arg("path"), py::arg("rgba"));
  m.def("_write_frame", &writeFrame, py::arg("path"), py::arg("rgba"), py::arg("depth"), py::arg("normal"),
        py::arg("albedo"), py::arg("instance"), py::arg("aov_format"), py::arg("scene"));
}

}  // namespace lenslab::python
