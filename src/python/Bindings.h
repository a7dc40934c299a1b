#pragma once
// The C++ part of the Python package (`lenslab._lenslab`, pybind11): what python/lenslab/ wraps.
// The objects hold the same C++ values the command line builds (a loaded Scene, a SelectedCamera),
// and go through the same readers and checks, so a refusal is the command line's one line, raised
// as ValueError (an InputError) or RuntimeError (no GL context, ...).
#include "camera/PhysicalCamera.h"
#include "scene/Scene.h"

#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace lenslab::python {

// A loaded scene, shared: a renderer keeps the scene it uploaded alive while it holds it.
struct PyScene {
  std::shared_ptr<const Scene> scene;
  std::filesystem::path path;
  std::optional<std::filesystem::path> defaultCameraFile;  // the bundled scene's camera file
};

// A camera as the command line selects one (a file's, a glTF camera, a COLMAP image's ...):
// near and far are fitted to each scene it renders.
struct PyCamera {
  SelectedCamera selected;
};

void bindScene(pybind11::module_& m);
void bindCamera(pybind11::module_& m);
void bindRenderer(pybind11::module_& m);
void bindFiles(pybind11::module_& m);
void bindSequence(pybind11::module_& m);

}  // namespace lenslab::python
