// lenslab.read_image and write_image: image files through the command line's own reader and writer
// (OpenImageIO; PNG 8-bit sRGB, EXR linear float, written whole or not at all), so that a frame
// written from Python is the file `lenslab render --out` writes of the same pixels.
#include "core/Error.h"
#include "core/Text.h"
#include "io/ImageFile.h"
#include "python/Arrays.h"
#include "python/Bindings.h"

#include <pybind11/stl/filesystem.h>

#include <algorithm>

namespace lenslab::python {
namespace py = pybind11;

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
}

}  // namespace lenslab::python
