#pragma once
// lenslab.Sequence's C++ state: `lenslab capture`'s options, frames' cameras and frame machinery
// (app/CaptureFrame.h) over the sequence's own copy of the scene, which it poses at each frame's
// time. A lenslab.Renderer renders its frames (Renderer.render_frame in RendererBinding.cpp).
#include "app/CaptureFrame.h"
#include "app/FrameCameras.h"
#include "io/FrameSequence.h"
#include "scene/Scene.h"

#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace lenslab::python {

struct PySequence {
  std::unique_ptr<CaptureOptions> options;  // FrameCameras and CaptureFrames keep references to it
  std::shared_ptr<Scene> scene;             // posed frame by frame: the sequence's own copy
  std::unique_ptr<FrameCameras> cameras;
  std::unique_ptr<CaptureFrames> frames;
  int frameCount = 0;
  std::vector<int> frameNumbers;  // of `frames=` (its step), in order
  std::filesystem::path manifest;
  std::vector<std::string> notes;  // warnings not yet handed to Python
};

// A frame of a sequence, kept whole so that lenslab.write writes exactly what was rendered; the
// Python arrays are read-only views of it.
struct PyCapturedFrame {
  std::shared_ptr<CapturedFrame> frame;
  std::shared_ptr<PySequence> sequence;
};

void bindSequence(pybind11::module_& m);

}  // namespace lenslab::python
