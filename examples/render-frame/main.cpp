// render-frame: the bundled rows scene through a thin lens, rendered headless with lenslab's
// library and written to a PNG (docs/install.md).
//   render-frame OUT.png [WIDTH [F_NUMBER]]      e.g. render-frame rows-f2.png 480 2
#include "camera/PhysicalCamera.h"
#include "gl/GlContext.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::cerr << "usage: render-frame OUT.png [WIDTH [F_NUMBER]]\n";
    return 2;
  }
  try {
    const int width = argc > 2 ? std::stoi(argv[2]) : 480;
    const double fNumber = argc > 3 ? std::stod(argv[3]) : 2.0;

    // ROWS_SCENE: set by CMakeLists.txt from the package's lenslab_ASSET_DIR.
    const lenslab::Scene scene = lenslab::loadGltf(ROWS_SCENE);

    // The camera as a photographer gives it (assets/rows/camera.json with the aperture opened):
    // a 35 mm lens on a 36 × 24 mm sensor, 3 m in front of the rows, focused on the 4 m box.
    lenslab::PhysicalCamera lens;
    lens.eye = {0.0, 1.0, 3.0};
    lens.target = {0.0, 0.55, -2.0};
    lens.focalLengthMm = 35.0;
    lens.focusDistance = 4.0;
    lens.fNumber = fNumber;  // aperture radius f / 2N
    lenslab::validate(lens, "render-frame's camera");
    // The lecture's viewing description (VRP, VPN, VUP, PRP, window on the plane of focus) and
    // the thin lens.
    const lenslab::Camera camera = lenslab::toCamera(lens, "render-frame");
    const lenslab::ImageSize size = lenslab::resolveImageSize(camera, width, std::nullopt);

    // An OpenGL 4.5 core context without a window (OSMesa: llvmpipe on the CPU, anywhere).
    const auto context = lenslab::createHeadlessContext(lenslab::Backend::OSMesa);
    lenslab::Renderer renderer(scene);
    // 32 points of the aperture, a pinhole view from each, averaged: everything off the plane of
    // focus blurs over its circle of confusion. Sobol' points, as `lenslab render` by default.
    const lenslab::PlanOptions options(lenslab::AperturePattern::Sobol, 32, 256, /*seed=*/1);
    const lenslab::FramePlan plan = lenslab::makeFramePlan(scene, camera, size, options);
    const lenslab::Image image = renderer.render(camera, plan, size);

    lenslab::writeImage(argv[1], image);  // linear light in, sRGB-encoded PNG out
    std::cout << "render-frame: wrote " << argv[1] << " (" << image.width << "x" << image.height << ", f/" << fNumber
              << ", " << plan.apertureSamples << " aperture samples, " << context->renderer() << ")\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "render-frame: " << e.what() << "\n";
    return 1;
  }
}
