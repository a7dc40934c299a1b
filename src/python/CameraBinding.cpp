// The Camera object: every form the command line reads, through its readers (so the same checks and
// one-line messages), and back out as the files vision tools read. python/lenslab/_camera.py builds
// the lecture, physical and OpenCV forms as camera-file JSON and reads them here.
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"
#include "io/ColmapModel.h"
#include "python/Arrays.h"
#include "python/Bindings.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <limits>
#include <optional>

namespace lenslab::python {
namespace py = pybind11;

namespace {

PyCamera fromFile(const CameraFile& file) { return PyCamera{SelectedCamera{file.camera, file.physical}}; }

}  // namespace

void bindCamera(py::module_& m) {
  py::class_<PyCamera>(m, "_Camera")
      .def_property_readonly("source", [](const PyCamera& c) { return c.selected.camera.source; })
      .def_property_readonly(
          "perspective", [](const PyCamera& c) { return c.selected.camera.view.projection == Projection::Perspective; })
      .def_property_readonly("aperture_radius", [](const PyCamera& c) { return c.selected.camera.lens.apertureRadius; })
      .def_property_readonly("focus_distance", [](const PyCamera& c) { return c.selected.camera.focusDistance(); })
      .def_property_readonly("calibrated_size",
                             [](const PyCamera& c) -> std::optional<py::tuple> {
                               const auto& size = c.selected.camera.calibratedSize;
                               if (!size) return std::nullopt;
                               return py::make_tuple(size->widthPx, size->heightPx);
                             })
      .def(
          "image_size",
          [](const PyCamera& c, std::optional<int> width, std::optional<int> height) {
            const ImageSize size = resolveImageSize(c.selected.camera, width, height);
            return py::make_tuple(size.widthPx, size.heightPx);
          },
          py::arg("width") = py::none(), py::arg("height") = py::none())
      // The OpenCV form (K, R, t, distCoeffs, focus and aperture) of a perspective camera on an
      // image of that size: read back, the same camera.
      .def(
          "_opencv_json",
          [](const PyCamera& c, std::optional<int> width, std::optional<int> height) {
            return toOpenCvCameraJson(c.selected.camera, resolveImageSize(c.selected.camera, width, height), false,
                                      false);
          },
          py::arg("width") = py::none(), py::arg("height") = py::none())
      // Where each world point shows on an image of that size, green's (through the lens's
      // distortion), in lenslab's pixels ((0, 0) the top-left corner); NaN for a point not in front
      // of the lens centre. The map the renderers and the flow AOV use (camera/ImageMap.h).
      .def(
          "_project",
          [](const PyCamera& c, const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
             std::optional<int> width, std::optional<int> height) {
            if (points.ndim() != 2 || points.shape(1) != 3)
              throw InputError("lenslab.Camera.project: give the points as an array of shape (N, 3)");
            const auto p = points.unchecked<2>();
            std::vector<double> pixels(static_cast<std::size_t>(p.shape(0)) * 2,
                                       std::numeric_limits<double>::quiet_NaN());
            {
              py::gil_scoped_release release;
              const ThinLensMap map(c.selected.camera, resolveImageSize(c.selected.camera, width, height));
              for (py::ssize_t i = 0; i < p.shape(0); ++i) {
                if (const auto pixel = map.pixelOfPoint({p(i, 0), p(i, 1), p(i, 2)})) {
                  pixels[2 * i] = pixel->x;
                  pixels[2 * i + 1] = pixel->y;
                }
              }
            }
            return arrayOf(std::move(pixels), {p.shape(0), 2});
          },
          py::arg("points"), py::arg("width") = py::none(), py::arg("height") = py::none())
      .def("_lecture_json", [](const PyCamera& c) { return toCameraJson(c.selected.camera); });

  m.def(
      "_camera_from_json",
      [](const std::string& text, const std::string& where) { return fromFile(parseCameraJson(text, where)); },
      py::arg("text"), py::arg("where"));
  m.def(
      "_camera_from_file", [](const std::filesystem::path& path) { return fromFile(loadCameraJson(path)); },
      py::arg("path"));
  m.def(
      "_camera_from_colmap",
      [](const std::filesystem::path& folder, const std::string& image) {
        return PyCamera{SelectedCamera{colmapImageCamera(readColmapModel(folder), image), std::nullopt}};
      },
      py::arg("folder"), py::arg("image"));
}

}  // namespace lenslab::python
