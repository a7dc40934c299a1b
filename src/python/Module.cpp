// lenslab._lenslab: the module's entry point. Errors a user can act on (InputError: a bad file,
// field or number) become ValueError with the command line's message.
#include "core/DataPaths.h"
#include "core/Error.h"
#include "python/Bindings.h"

#include <string>

namespace py = pybind11;

PYBIND11_MODULE(_lenslab, m) {
  m.doc() = "lenslab's renderers and camera model (C++); use the `lenslab` package, which wraps it";
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const lenslab::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  // Data (the bundled scenes) is found from this module's file, as the executable finds it from
  // its own (core/DataPaths.h).
  m.def(
      "_set_module_file", [](const std::string& file) { lenslab::setEmbeddingLibrary(file); }, py::arg("file"));
  m.def(
      "asset_directory", [] { return lenslab::assetDirectory().string(); },
      "The bundled scenes' folder (rows/, grid/, ...), as the command line finds it.");
  lenslab::python::bindScene(m);
  lenslab::python::bindCamera(m);
  lenslab::python::bindRenderer(m);
  lenslab::python::bindFiles(m);
  lenslab::python::bindSequence(m);
}
