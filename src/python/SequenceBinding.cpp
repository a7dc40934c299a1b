// lenslab.Sequence: the frames `lenslab capture` would render — along a camera path, down a list
// of cameras (objects, a JSON-lines file or a COLMAP model's images), or through the scene's own
// camera over its animation — with the capture's checks, frame numbers, seeds, cameras and files.
// Its frames come from a lenslab.Renderer (Renderer.render_frame), and lenslab.write commits one
// as capture does: image, AOV files, camera file and manifest line, the same bytes.
#include "app/CaptureColmap.h"
#include "app/CaptureManifest.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/Progress.h"
#include "python/Bindings.h"
#include "python/Sequence.h"

#include <pybind11/stl.h>

#include <optional>

namespace lenslab::python {
namespace py = pybind11;

namespace {

struct SequenceRequest {
  std::string path, camerasFile, colmap, cameraFile, cameraNode, frames, out, manifest, colmapOut, colmapFormat;
  std::optional<std::vector<PyCamera>> cameras;
  std::optional<double> fps;
  std::optional<int> width, height;
  std::vector<std::string> aovs;
  std::string aovFormat, normals, apertureSamples, pattern;
  std::uint32_t seed = 1;
};

std::shared_ptr<PySequence> makeSequence(const PyScene& scene, const SequenceRequest& r) {
  auto s = std::make_shared<PySequence>();
  s->options = std::make_unique<CaptureOptions>();
  CaptureOptions& o = *s->options;
  o.pathFile = r.path;
  o.camerasFile = r.camerasFile;
  o.camera.colmapDir = r.colmap;
  o.cameraFile = r.cameraFile;
  o.camera.cameraNode = r.cameraNode;
  o.fps = r.fps ? std::optional<double>(checkedNumber("fps", *r.fps, kFramesPerSecondRange)) : std::nullopt;
  o.width = r.width;
  o.height = r.height;
  o.frames = r.frames;
  o.out = r.out;
  o.manifest = r.manifest;
  o.colmapOut = r.colmapOut;
  o.colmapFormat = r.colmapFormat;
  o.aovs = AovRequest{r.aovs, r.aovFormat, r.normals};
  o.lens.apertureSamples = r.apertureSamples;
  o.lens.pattern = r.pattern;
  o.lens.seed = r.seed;
  o.quiet = false;
  const int sources = !r.path.empty() + !r.camerasFile.empty() + r.cameras.has_value() + !r.colmap.empty();
  if (sources > 1)
    throw InputError("lenslab.Sequence: give one of path, cameras and colmap (each gives every frame's camera)");
  if (o.colmapFormat != "text" && o.colmapFormat != "binary")
    throw InputError(cat("colmap_format \"", o.colmapFormat, "\": give \"text\" or \"binary\""));
  if (r.cameras) {
    std::vector<ListedCamera> list;
    const double fps = r.fps.value_or(24.0);
    for (std::size_t i = 0; i < r.cameras->size(); ++i) {
      const SelectedCamera& c = (*r.cameras)[i].selected;
      CameraFile file;
      file.form = c.physical ? CameraFile::Form::Physical : CameraFile::Form::Intrinsics;
      file.camera = c.camera;
      file.physical = c.physical;
      list.push_back(ListedCamera{static_cast<double>(i) / fps, std::move(file), cat("cameras[", i, "]")});
    }
    o.cameraList = std::move(list);
  }
  s->scene = std::make_shared<Scene>(*scene.scene);
  Scene& posed = *s->scene;
  s->cameras =
      std::make_unique<FrameCameras>(o, posed, o.width && o.height ? static_cast<double>(*o.width) / *o.height : 0.0);
  s->frameCount = s->cameras->frameCount(posed);
  const FrameRange range =
      o.frames.empty() ? FrameRange{0, s->frameCount - 1} : parseFrameRange(o.frames, s->frameCount);
  s->frameNumbers = shardFrames(range, Shard{});
  checkFramePattern(o.out, "--out");
  const AovOutput aovs = parseAovRequest(o.aovs, true);
  s->manifest = o.manifest.empty() ? defaultManifest(o.out) : std::filesystem::path(o.manifest);
  OutputSet folders;
  checkCaptureOutputs(o, s->frameNumbers, range, s->manifest, aovs, folders);
  if (!o.colmapOut.empty()) {
    OutputSet model;
    ProgressReporter progress("lenslab.Sequence: colmap_out", "frames", true);
    PySequence* raw = s.get();
    writeColmapModel(o, *s->cameras, posed, range, o.colmapOut, model, progress,
                     [raw](const std::string& line) { raw->notes.push_back(line); });
    model.commit();
  }
  folders.commit();
  PySequence* raw = s.get();  // the notes wait there for Python's warnings
  s->frames =
      std::make_unique<CaptureFrames>(o, posed, *s->cameras, aovs, std::nullopt, Shard{}, range.first, s->frameCount,
                                      [raw](const std::string& line) { raw->notes.push_back(line); });
  return s;
}

std::vector<std::string> takeNotes(PySequence& s) {
  std::vector<std::string> notes;
  notes.swap(s.notes);
  for (std::string& n : notes)
    if (n.rfind("lenslab: warning: ", 0) == 0) n.erase(0, 18);
  return notes;
}

}  // namespace

void bindSequence(py::module_& m) {
  py::class_<PySequence, std::shared_ptr<PySequence>>(m, "_Sequence")
      .def(py::init([](const PyScene& scene, std::string path, std::string camerasFile,
                       std::optional<std::vector<PyCamera>> cameras, std::string colmap, std::string cameraFile,
                       std::string cameraNode, std::optional<double> fps, std::optional<int> width,
                       std::optional<int> height, std::string frames, std::string out, std::string manifest,
                       std::vector<std::string> aovs, std::string aovFormat, std::string normals,
                       std::string apertureSamples, std::string pattern, std::uint32_t seed, std::string colmapOut,
                       std::string colmapFormat) {
             SequenceRequest r;
             r.path = std::move(path), r.camerasFile = std::move(camerasFile), r.cameras = std::move(cameras);
             r.colmap = std::move(colmap), r.cameraFile = std::move(cameraFile), r.cameraNode = std::move(cameraNode);
             r.fps = fps, r.width = width, r.height = height, r.frames = std::move(frames), r.out = std::move(out);
             r.manifest = std::move(manifest), r.aovs = std::move(aovs), r.aovFormat = std::move(aovFormat);
             r.normals = std::move(normals), r.apertureSamples = std::move(apertureSamples);
             r.pattern = std::move(pattern), r.seed = seed, r.colmapOut = std::move(colmapOut);
             r.colmapFormat = std::move(colmapFormat);
             py::gil_scoped_release release;
             return makeSequence(scene, r);
           }),
           py::arg("scene"), py::arg("path"), py::arg("cameras_file"), py::arg("cameras"), py::arg("colmap"),
           py::arg("camera_file"), py::arg("camera_node"), py::arg("fps"), py::arg("width"), py::arg("height"),
           py::arg("frames"), py::arg("out"), py::arg("manifest"), py::arg("aovs"), py::arg("aov_format"),
           py::arg("normals"), py::arg("aperture_samples"), py::arg("pattern"), py::arg("seed"), py::arg("colmap_out"),
           py::arg("colmap_format"))
      .def_readonly("frame_numbers", &PySequence::frameNumbers)
      .def_readonly("frame_count", &PySequence::frameCount)
      .def_property_readonly("manifest", [](const PySequence& s) { return s.manifest.string(); })
      .def_property_readonly("out", [](const PySequence& s) { return s.options->out; })
      .def("time", [](const PySequence& s, int frame) { return s.cameras->timeOf(frame); })
      .def("image_file", [](const PySequence& s, int frame) { return formatFramePath(s.options->out, frame); })
      .def("take_notes", [](PySequence& s) { return takeNotes(s); });

  py::class_<PyCapturedFrame>(m, "_CapturedFrame").def("write", [](PyCapturedFrame& c) {
    std::string line;
    {
      py::gil_scoped_release release;
      PySequence& s = *c.sequence;
      line = s.frames->commit(*c.frame, formatFramePath(s.options->out, c.frame->frame), s.manifest).dump();
    }
    return line;
  });
}

}  // namespace lenslab::python
