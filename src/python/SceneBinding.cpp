// lenslab.load and the Scene object: a glTF file loaded once (the command line's loader, checks and
// messages), posed at a time of its animations, with the camera a command would choose for it.
#include "core/Error.h"
#include "core/Text.h"
#include "plan/CameraSelection.h"
#include "plan/SceneChoice.h"
#include "plan/UserOptions.h"
#include "python/Bindings.h"
#include "scene/GltfLoader.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <tuple>
#include <vector>

namespace lenslab::python {
namespace py = pybind11;
namespace fs = std::filesystem;

namespace {

// The scene at `path` (empty: the bundled rows scene), posed as `render --animation --time` poses
// it; `warnings` gets what the command line would warn of. The load itself runs without the GIL.
PyScene load(const std::string& path, const std::string& animation, std::optional<double> timeSeconds,
             std::optional<std::tuple<float, float, float>> background, std::vector<std::string>& warnings) {
  const SceneAndCamera files = resolveSceneAndCamera(path, "", "camera.json");
  auto scene = std::make_shared<Scene>(loadGltf(files.scene));
  if (background)
    applyBackground(*scene, glm::vec3(std::get<0>(*background), std::get<1>(*background), std::get<2>(*background)));
  warnings = poseForOneImage(*scene, animation, timeSeconds);
  if (scene->triangleCount() == 0)
    throw InputError(cat(files.scene.string(), ": the scene has no triangles to render"));
  return PyScene{std::move(scene), files.scene, files.camera};
}

py::tuple vec3(const glm::dvec3& v) { return py::make_tuple(v.x, v.y, v.z); }

}  // namespace

void bindScene(py::module_& m) {
  py::class_<PyScene>(m, "Scene", "A glTF 2.0 scene, loaded and posed (lenslab.load)")
      .def_property_readonly("path", [](const PyScene& s) { return s.path; })
      .def_property_readonly("triangle_count", [](const PyScene& s) { return s.scene->triangleCount(); })
      .def_property_readonly(
          "bounds",
          [](const PyScene& s) { return py::make_tuple(vec3(s.scene->bounds.min), vec3(s.scene->bounds.max)); },
          "((xmin, ymin, zmin), (xmax, ymax, zmax)), world units")
      .def_property_readonly(
          "cameras",
          [](const PyScene& s) {
            std::vector<std::string> labels;
            for (std::size_t i = 0; i < s.scene->cameras.size(); ++i) labels.push_back(sceneCameraLabel(*s.scene, i));
            return labels;
          },
          "The glTF cameras, as `lenslab info` lists them")
      .def_property_readonly(
          "clips",
          [](const PyScene& s) {
            std::vector<std::string> names;
            for (const auto& clip : s.scene->animation.clips) names.push_back(clip.name);
            return names;
          },
          "The animation clips' names, in the file's order")
      .def_property_readonly(
          "instances",
          [](const PyScene& s) {
            std::vector<std::tuple<int, std::string>> nodes;
            for (const Instance& instance : s.scene->instances)
              nodes.emplace_back(instance.gltfNode, instance.gltfNodeName);
            return nodes;
          },
          "(glTF node index, node name) of each instance drawn: what the instance AOV reports")
      .def_property_readonly("notes", [](const PyScene& s) { return s.scene->notes; })
      .def("__repr__", [](const PyScene& s) {
        return cat("<lenslab.Scene ", s.path.string(), ": ", s.scene->triangleCount(), " triangles, ",
                   s.scene->cameras.size(), " cameras>");
      });

  m.def(
      "_load",
      [](const std::string& path, const std::string& animation, std::optional<double> timeSeconds,
         std::optional<std::tuple<float, float, float>> background) {
        std::vector<std::string> warnings;
        PyScene scene;
        {
          py::gil_scoped_release release;
          scene = load(path, animation, timeSeconds, background, warnings);
        }
        return py::make_tuple(scene, warnings);
      },
      py::arg("path"), py::arg("animation"), py::arg("time"), py::arg("background"));

  // The camera `render SCENE` would use with `--camera-node NODE` (empty: its default: the bundled
  // scene's camera file, the first glTF camera, else automatic framing); `aspect` as the command
  // line's --width / --height when both are given, else 0.
  m.def(
      "_scene_camera",
      [](const PyScene& scene, const std::string& node, double aspect) {
        CameraOptions options;
        options.cameraNode = node;
        const std::optional<fs::path> file = node.empty() ? scene.defaultCameraFile : std::nullopt;
        return PyCamera{chooseCamera(*scene.scene, file, options, aspect)};
      },
      py::arg("scene"), py::arg("node"), py::arg("aspect"));
}

}  // namespace lenslab::python
