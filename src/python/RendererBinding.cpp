// lenslab.Renderer: a GL context, its compiled programs and the uploaded scene kept open across
// frames, so that a sequence costs frames, not process starts. Each frame is the command line's:
// the camera's near and far fitted to the scene, the image size resolved, the frame planned (a
// pinhole depth pre-pass when it chooses the count) and rendered (app/FrameRender.h), the AOVs
// from the ray caster along the pixel-centre rays. The GIL is released while it works.
//
// A GL context is current on one thread: the renderer answers only the thread that made it, and
// refuses any other by name (a Renderer per thread works: each has its own context).
#include "app/FrameRender.h"
#include "camera/DepthRange.h"
#include "camera/ImageMap.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AovFiles.h"
#include "plan/UserOptions.h"
#include "python/Arrays.h"
#include "python/Bindings.h"
#include "python/Sequence.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"

#include <pybind11/stl.h>

#include <optional>
#include <thread>

namespace lenslab::python {
namespace py = pybind11;

namespace {

// What one frame gives back before it becomes NumPy arrays (made with the GIL held).
struct Frame {
  Image image;
  AovImages aovs;
  int samples = 0;
  std::vector<std::string> warnings;
  SelectedCamera camera;  // as rendered: near and far fitted to the scene
};

struct FrameRequest {
  std::optional<int> width, height;
  std::uint32_t seed = 1;
  std::vector<std::string> aovs;
  std::string normals = "gl";
};

class PyRenderer {
 public:
  PyRenderer(std::optional<int> width, std::optional<int> height, const std::string& backend)
      : width_(width), height_(height), owner_(std::this_thread::get_id()) {
    if (backend != "osmesa" && backend != "egl")
      throw InputError(cat("lenslab.Renderer: backend \"", backend, "\": give \"osmesa\" (CPU, anywhere) or \"egl\""));
    py::gil_scoped_release release;
    context_ = createHeadlessContext(backend == "egl" ? Backend::Egl : Backend::OSMesa);
  }
  ~PyRenderer() {
    // The GL objects go while their context is current.
    if (renderer_) context_->makeCurrent();
    renderer_.reset();
  }
  PyRenderer(const PyRenderer&) = delete;
  PyRenderer& operator=(const PyRenderer&) = delete;

  std::string glRenderer() {
    checkThread("gl_renderer");
    context_->makeCurrent();
    return context_->renderer();
  }

  Frame render(const PyScene& scene, const PyCamera& camera, const std::string& apertureSamples,
               const std::string& pattern, const FrameRequest& request) {
    checkThread("render");
    LensOptions lens;
    lens.apertureSamples = apertureSamples;
    lens.pattern = pattern;
    lens.seed = request.seed;
    const PlanOptions planOptions = toPlanOptions(lens);
    const AovOutput aovs = aovOutputOf(request);
    Frame frame;
    frame.camera = preparedCamera(scene, camera);
    const ImageSize size = sizeFor(frame.camera, request);
    context_->makeCurrent();
    requireOneTarget(size, queryRenderTargetLimits(), "lenslab.Renderer.render");
    Renderer& renderer = rendererFor(scene.scene);
    RunStats stats;
    const FramePlan plan = planFrame(renderer, *scene.scene, frame.camera.camera, size, planOptions, stats);
    frame.warnings = plan.warnings;
    frame.image = renderPlanned(renderer, frame.camera.camera, plan, size, stats, nullptr, true);
    frame.samples = plan.apertureSamples;
    frame.aovs = aovImagesOf(scene, ThinLensMap(frame.camera.camera, size), aovs);
    return frame;
  }

  Frame raycast(const PyScene& scene, const PyCamera& camera, int samplesPerPixel, const FrameRequest& request) {
    checkThread("raycast");
    if (samplesPerPixel < 1)
      throw InputError(cat("lenslab.Renderer.raycast: spp ", samplesPerPixel, ": give at least 1 sample per pixel"));
    const AovOutput aovs = aovOutputOf(request);
    Frame frame;
    frame.camera = preparedCamera(scene, camera);
    const ImageSize size = sizeFor(frame.camera, request);
    const ThinLensMap map(frame.camera.camera, size);
    frame.image = casterFor(scene).render(map, RaycastOptions{samplesPerPixel, request.seed});
    frame.samples = samplesPerPixel;
    frame.aovs = aovImagesOf(scene, map, aovs);
    return frame;
  }

  // Frame `frame` of `sequence`, as capture renders it.
  std::shared_ptr<CapturedFrame> renderFrame(PySequence& sequence, int frame) {
    checkThread("render_frame");
    context_->makeCurrent();
    return std::make_shared<CapturedFrame>(sequence.frames->render(frame, rendererFor(sequence.scene)));
  }

 private:
  void checkThread(const char* method) const {
    if (std::this_thread::get_id() != owner_)
      throw std::runtime_error(cat("lenslab.Renderer.", method,
                                   ": called from a thread other than the one that made the renderer, whose GL "
                                   "context is current there; make one Renderer per thread"));
  }

  static SelectedCamera preparedCamera(const PyScene& scene, const PyCamera& camera) {
    SelectedCamera selected = camera.selected;
    selected.camera = withDepthRangeFitted(selected.camera, scene.scene->bounds);
    return selected;
  }

  ImageSize sizeFor(const SelectedCamera& camera, const FrameRequest& request) const {
    const bool either = request.width || request.height;
    return resolveImageSize(camera.camera, either ? request.width : width_, either ? request.height : height_);
  }

  static AovOutput aovOutputOf(const FrameRequest& request) {
    AovOutput output;
    output.selection = parseAovs(request.aovs, "aovs");
    if (output.selection.flow)
      throw InputError("aovs: \"flow\" is the motion to the next frame of a sequence; a single frame has none");
    output.normals = parseNormalConvention(request.normals);
    return output;
  }

  AovImages aovImagesOf(const PyScene& scene, const ImageMap& map, const AovOutput& output) {
    if (!output.selection.any()) return {};
    AovImages images = casterFor(scene).aovImages(map, output.selection);
    applyNormalConvention(images, output.normals);
    return images;
  }

  // The renderer of the scene last rendered, kept (with the scene) until another scene is.
  Renderer& rendererFor(const std::shared_ptr<const Scene>& scene) {
    if (!renderer_ || rasterScene_ != scene) {
      renderer_.reset();
      rasterScene_ = scene;
      renderer_ = std::make_unique<Renderer>(*rasterScene_);
    }
    return *renderer_;
  }
  const RayCaster& casterFor(const PyScene& scene) {
    if (!caster_ || castScene_ != scene.scene) {
      caster_.reset();
      castScene_ = scene.scene;
      caster_ = std::make_unique<RayCaster>(*castScene_);
    }
    return *caster_;
  }

  std::optional<int> width_, height_;
  std::thread::id owner_;
  std::unique_ptr<GlContext> context_;
  std::shared_ptr<const Scene> rasterScene_;
  std::unique_ptr<Renderer> renderer_;
  std::shared_ptr<const Scene> castScene_;
  std::unique_ptr<RayCaster> caster_;
};

// Float AOV channels of `count` a pixel as (H, W[, count]) arrays.
py::array_t<float> floatsOf(std::vector<float>&& values, int width, int height, int count) {
  if (count == 1) return arrayOf(std::move(values), {height, width});
  return arrayOf(std::move(values), {height, width, count});
}

// The frame as Python sees it: NumPy arrays owning the buffers (no copy), instance ids as int32
// glTF node indices (−1 where nothing is hit).
py::dict toPython(Frame&& frame) {
  py::dict d;
  const int w = frame.image.width, h = frame.image.height;
  d["rgba"] = arrayOf(std::move(frame.image.rgba), {h, w, 4});
  AovImages& a = frame.aovs;
  if (!a.depth.empty()) d["depth"] = floatsOf(std::move(a.depth), w, h, 1);
  if (!a.normal.empty()) d["normal"] = floatsOf(std::move(a.normal), w, h, 3);
  if (!a.albedo.empty()) d["albedo"] = floatsOf(std::move(a.albedo), w, h, 3);
  if (!a.instance.empty()) {
    std::vector<std::int32_t> ids(a.instance.begin(), a.instance.end());
    d["instance"] = arrayOf(std::move(ids), {h, w});
  }
  d["samples"] = frame.samples;
  d["warnings"] = frame.warnings;
  d["camera"] = PyCamera{std::move(frame.camera)};
  return d;
}

// A sequence's frame as Python sees it: read-only views of what lenslab.write writes (normals in
// the OpenCV convention and instance ids as int32 are copies), its frame number, time, seed and
// camera, and the frame itself for lenslab.write.
py::dict toPython(const PyCapturedFrame& captured) {
  const CapturedFrame& c = *captured.frame;
  const std::shared_ptr<const void> owner = captured.frame;
  py::dict d;
  const int w = c.image.width, h = c.image.height;
  d["rgba"] = readOnlyView(c.image.rgba, {h, w, 4}, owner);
  const AovImages& a = c.aovs;
  if (!a.depth.empty()) d["depth"] = readOnlyView(a.depth, {h, w}, owner);
  if (!a.normal.empty()) {
    if (captured.sequence->frames->aovs().normals == NormalConvention::Gl) {
      d["normal"] = readOnlyView(a.normal, {h, w, 3}, owner);
    } else {
      AovImages normals;
      normals.normal = a.normal;
      applyNormalConvention(normals, captured.sequence->frames->aovs().normals);
      d["normal"] = floatsOf(std::move(normals.normal), w, h, 3);
    }
  }
  if (!a.albedo.empty()) d["albedo"] = readOnlyView(a.albedo, {h, w, 3}, owner);
  if (!a.instance.empty()) {
    std::vector<std::int32_t> ids(a.instance.begin(), a.instance.end());
    d["instance"] = arrayOf(std::move(ids), {h, w});
  }
  if (!a.flow.empty()) d["flow"] = readOnlyView(a.flow, {h, w, 2}, owner);
  d["samples"] = c.stats.estimate ? c.stats.estimate->meanSamples : static_cast<double>(c.apertureSamples);
  d["warnings"] = std::vector<std::string>{};
  d["camera"] =
      PyCamera{SelectedCamera{c.camera, c.key.key ? std::optional<PhysicalCamera>(c.key.key->camera) : std::nullopt}};
  d["index"] = c.frame;
  d["time"] = c.timeSeconds;
  d["seed"] = c.seed;
  d["captured"] = captured;
  return d;
}

FrameRequest requestOf(std::optional<int> width, std::optional<int> height, std::uint32_t seed,
                       std::vector<std::string> aovs, std::string normals) {
  return FrameRequest{width, height, seed, std::move(aovs), std::move(normals)};
}

}  // namespace

void bindRenderer(py::module_& m) {
  py::class_<PyRenderer>(m, "_Renderer")
      .def(py::init<std::optional<int>, std::optional<int>, const std::string&>(), py::arg("width"), py::arg("height"),
           py::arg("backend"))
      .def("gl_renderer", &PyRenderer::glRenderer)
      .def(
          "render",
          [](PyRenderer& r, const PyScene& scene, const PyCamera& camera, const std::string& apertureSamples,
             const std::string& pattern, std::optional<int> width, std::optional<int> height, std::uint32_t seed,
             std::vector<std::string> aovs, std::string normals) {
            const FrameRequest request = requestOf(width, height, seed, std::move(aovs), std::move(normals));
            Frame frame;
            {
              py::gil_scoped_release release;
              frame = r.render(scene, camera, apertureSamples, pattern, request);
            }
            return toPython(std::move(frame));
          },
          py::arg("scene"), py::arg("camera"), py::arg("aperture_samples"), py::arg("pattern"), py::arg("width"),
          py::arg("height"), py::arg("seed"), py::arg("aovs"), py::arg("normals"))
      .def(
          "raycast",
          [](PyRenderer& r, const PyScene& scene, const PyCamera& camera, int spp, std::optional<int> width,
             std::optional<int> height, std::uint32_t seed, std::vector<std::string> aovs, std::string normals) {
            const FrameRequest request = requestOf(width, height, seed, std::move(aovs), std::move(normals));
            Frame frame;
            {
              py::gil_scoped_release release;
              frame = r.raycast(scene, camera, spp, request);
            }
            return toPython(std::move(frame));
          },
          py::arg("scene"), py::arg("camera"), py::arg("spp"), py::arg("width"), py::arg("height"), py::arg("seed"),
          py::arg("aovs"), py::arg("normals"))
      .def(
          "render_frame",
          [](PyRenderer& r, const std::shared_ptr<PySequence>& sequence, int frame) {
            PyCapturedFrame captured{nullptr, sequence};
            {
              py::gil_scoped_release release;
              captured.frame = r.renderFrame(*sequence, frame);
            }
            return toPython(captured);
          },
          py::arg("sequence"), py::arg("frame"));
}

}  // namespace lenslab::python
