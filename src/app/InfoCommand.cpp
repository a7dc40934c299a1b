// lenslab info: what a scene holds and what a render of it would need.
#include "app/CliOptions.h"
#include "app/Commands.h"
#include "camera/DepthRange.h"
#include "camera/ImageSize.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "plan/CameraSelection.h"
#include "gl/GlContext.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "render/VisibleBlurPass.h"
#include "scene/GltfLoader.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

namespace lenslab {
namespace {

constexpr double kDegreesPerRadian = 57.29577951308232;

void printVector(std::ostream& out, const glm::dvec3& v) { out << "[" << v.x << ", " << v.y << ", " << v.z << "]"; }

// The visible-blur pre-pass needs a GL context: one is made (OSMesa) only for a camera with an
// aperture; without one, the plan says what the bounds say.
std::optional<VisibleBlur> measureBlur(const Scene& scene, const Camera& camera, ImageSize size, std::ostream& out) {
  if (camera.lens.isPinhole()) return std::nullopt;
  try {
    const std::unique_ptr<GlContext> context = createHeadlessContext(Backend::OSMesa);
    Renderer renderer(scene);
    return measureVisibleBlur(renderer, camera, size);
  } catch (const std::exception& e) {
    out << "note        no pre-pass (" << e.what() << "): the plan below is from the scene's bounds\n";
    return std::nullopt;
  }
}

// The scene's cameras, each as glTF gives it and where it stands.
void printCameras(std::ostream& out, const Scene& scene) {
  out << "cameras     " << scene.cameras.size()
      << (scene.cameras.empty() ? "" : " (render --camera-node NAME|INDEX picks one; default: [0])") << "\n";
  for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
    const SceneCamera& c = scene.cameras[i];
    out << "  " << sceneCameraLabel(scene, i) << ": ";
    if (c.perspective)
      out << "perspective, yfov " << c.yfovRadians * kDegreesPerRadian << " deg, aspect "
          << (c.aspectRatio > 0 ? std::to_string(c.aspectRatio) : "from image");
    else
      out << "orthographic, xmag " << c.xmag << ", ymag " << c.ymag;
    out << ", znear " << c.znear << ", zfar " << c.zfar << ", at ";
    printVector(out, glm::dvec3(c.worldFromCamera[3]));
    out << "\n";
  }
}

// The animation clips, with how many of their channels lenslab plays.
void printAnimations(std::ostream& out, const Scene& scene) {
  const std::vector<AnimationClip>& clips = scene.animation.clips;
  out << "animations  " << clips.size()
      << (clips.empty() ? "" : " (--animation NAME|INDEX|all picks what plays; default: [0])") << "\n";
  for (std::size_t i = 0; i < clips.size(); ++i)
    out << "  [" << i << "] " << (clips[i].name.empty() ? "(unnamed)" : "\"" + clips[i].name + "\"") << ": "
        << clipDurationSeconds(clips[i]) << " s, " << clips[i].fileChannelCount << " channel(s)"
        << (clips[i].channels.size() < clips[i].fileChannelCount ? cat(", ", clips[i].channels.size(), " played")
                                                                 : std::string())
        << "\n";
}

// The materials: the glTF factors and which maps and modes each uses.
void printMaterials(std::ostream& out, const Scene& scene) {
  out << "materials   " << scene.materials.size() << "\n";
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    out << "  [" << i << "] " << (m.name.empty() ? "(unnamed)" : m.name) << ": " << (m.unlit ? "unlit" : "lit")
        << ", base [" << m.baseColorFactor.r << ", " << m.baseColorFactor.g << ", " << m.baseColorFactor.b << ", "
        << m.baseColorFactor.a << "]" << (m.baseColorTexture.present() ? ", textured" : "")
        << (m.unlit ? std::string() : cat(", metallic ", m.metallicFactor, ", roughness ", m.roughnessFactor))
        << (m.metallicRoughnessTexture.present() ? ", metallic-roughness map" : "")
        << (m.occlusionTexture.present() ? ", occlusion map" : "") << (m.normalTexture.present() ? ", normal map" : "")
        << (m.alphaMode == AlphaMode::Mask    ? ", alpha mask"
            : m.alphaMode == AlphaMode::Blend ? ", alpha blend"
                                              : "")
        << (m.doubleSided ? ", double-sided" : "") << "\n";
  }
}

// The punctual lights (KHR_lights_punctual); without any, lenslab lights the scene itself.
void printLights(std::ostream& out, const Scene& scene) {
  out << "lights      " << scene.lights.size()
      << (scene.lights.empty() ? " (lenslab's default directional light)" : " (KHR_lights_punctual)") << "\n";
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const PunctualLight& l = scene.lights[i];
    static const char* const kTypes[] = {"directional", "point", "spot"};
    out << "  [" << i << "] " << (l.name.empty() ? "(unnamed)" : l.name) << ": " << kTypes[static_cast<int>(l.type)]
        << ", " << l.intensity << (l.type == LightType::Directional ? " lx" : " cd") << ", node " << l.gltfNode << "\n";
  }
}

// What a render of the scene with the chosen camera would do: its size, aperture samples and the
// blur the pre-pass sees, and each pass of the frame plan with why.
void printRenderPlan(std::ostream& out, const Scene& scene, const std::string& cameraFile,
                     const CameraOptions& cameraOptions) {
  if (scene.triangleCount() == 0) {
    out << "render      nothing to draw (no triangles)\n";
    return;
  }
  SelectedCamera selected = chooseCamera(
      scene, cameraFile.empty() ? std::nullopt : std::optional<std::filesystem::path>(cameraFile), cameraOptions, 0.0);
  selected.camera = withDepthRangeFitted(selected.camera, scene.bounds);
  const ImageSize size = resolveImageSize(selected.camera, std::nullopt, std::nullopt);
  const std::optional<VisibleBlur> visible = measureBlur(scene, selected.camera, size, out);
  const FramePlan plan = makeFramePlan(scene, selected.camera, size, {}, visible ? &*visible : nullptr);
  out << "render      camera: " << selected.camera.source << ", " << size.widthPx << "x" << size.heightPx << "\n";
  out << "            aperture samples: " << plan.apertureSamples << " (" << plan.samplesWhy << ")\n";
  if (plan.visible) {
    const VisibleBlurSummary& v = *plan.visible;
    out << "blur seen   circle of confusion over the image (pinhole depth pre-pass at " << v.prepass.widthPx << "x"
        << v.prepass.heightPx << ", dilated by nearer circles):\n"
        << "            <= 1 px " << 100.0 * v.fractions[0] << " %, 1-4 px " << 100.0 * v.fractions[1] << " %, 4-16 px "
        << 100.0 * v.fractions[2] << " %, 16-64 px " << 100.0 * v.fractions[3] << " %, > 64 px "
        << 100.0 * v.fractions[4] << " %\n"
        << "            median " << v.p50Px << " px, 90 % " << v.p90Px << " px, 99 % " << v.p99Px << " px, largest "
        << v.maxPx << " px\n"
        << "            the scene's bounds alone: up to " << v.boundsCocMaxPx << " px, " << v.boundsSamples
        << " samples\n";
  }
  for (const PlannedPass& p : plan.passes) {
    out << "            pass " << p.name << ": " << p.why;
    for (const std::string& v : p.variants) out << " [" << v << "]";
    out << "\n";
  }
}

int runInfo(const std::string& path, const std::string& cameraFile, const CameraOptions& cameraOptions) {
  const Scene scene = loadGltf(path);
  std::ostream& out = std::cout;
  out.precision(6);
  out << "scene       " << path << "\n";
  out << "triangles   " << scene.triangleCount() << " (" << scene.meshes.size() << " meshes, " << scene.instances.size()
      << " instances)\n";
  if (scene.bounds.empty()) {
    out << "bounds      empty\n";
  } else {
    out << "bounds      min ";
    printVector(out, scene.bounds.min);
    out << " max ";
    printVector(out, scene.bounds.max);
    out << " (size ";
    printVector(out, scene.bounds.size());
    out << ")\n";
  }
  printCameras(out, scene);
  printAnimations(out, scene);
  printMaterials(out, scene);
  out << "textures    " << scene.textures.size() << " (" << scene.images.size() << " images)\n";
  printLights(out, scene);
  for (const std::string& note : scene.notes) out << "note        " << note << "\n";

  printRenderPlan(out, scene, cameraFile, cameraOptions);
  return 0;
}

}  // namespace

std::function<int()> addInfoCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto camera = std::make_shared<std::string>();
  auto cameraOptions = std::make_shared<CameraOptions>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Describe a glTF scene: triangles, bounds, cameras, animations, materials, render plan");
  cmd->add_option("scene", *path, "glTF 2.0 scene (.gltf or .glb)")->required();
  cmd->add_option("--camera", *camera,
                  "camera JSON to plan for (default: the scene's first glTF camera, else an automatic framing)");
  addCameraNodeOption(*cmd, *cameraOptions);
  return [cmd, path, camera, cameraOptions]() { return cmd->parsed() ? runInfo(*path, *camera, *cameraOptions) : -1; };
}

}  // namespace lenslab
