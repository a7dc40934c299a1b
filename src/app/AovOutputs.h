#pragma once
// The AOVs asked for (--aov LIST, --aov-format, --normal-convention; the Python package's aovs=)
// and how they are written beside the image (core/Aovs.h): as EXR channels or as files of their own
// (io/AovFiles.h), and the instances.json that names their instance ids. No command-line library:
// the Python module writes through it too.
#include "core/Aovs.h"
#include "io/AovFiles.h"
#include "scene/Scene.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lenslab {

struct AovRequest {
  std::vector<std::string> names;  // --aov
  std::string format = "exr";      // --aov-format
  std::string normals = "gl";      // --normal-convention
};

// The request parsed. Throws InputError (one line) for --aov-format or --normal-convention without
// --aov, --normal-convention opencv without the normal AOV, or the flow AOV outside a sequence
// (`sequence`: capture's frames, which have a next frame).
AovOutput parseAovRequest(const AovRequest& request, bool sequence = false);

// Checks `image` and the AOV files beside it as outputs (OutputKind::Any), naming `outOption`.
void checkAovOutput(const AovOutput& output, const std::filesystem::path& image, const std::string& outOption);
// parseAovRequest, then checkAovOutput.
AovOutput checkedAovOutput(const AovRequest& request, const std::filesystem::path& image, const std::string& outOption);

// The AOV files of `images` beside `image` (io/AovFiles.h) into `outputs`, and with the instance
// AOV the ids' names in `instancesFile` (default: IMAGE.instances.json beside it); the channels
// the image itself takes. `warn` gets a line for each value a file could not hold.
std::vector<ImageChannel> addAovOutputs(OutputSet& outputs, const std::filesystem::path& image, const AovImages& images,
                                        const AovOutput& output, const Scene& scene,
                                        const std::function<void(const std::string&)>& warn,
                                        const std::filesystem::path& instancesFile = {});
// Where the instance names go beside `image` by default: IMAGE.instances.json.
std::filesystem::path instancesFileBeside(const std::filesystem::path& image);

// The instance ids' names, as JSON: {"background": 0, "instances": [{"id", "node", "node_name",
// "mesh", "materials"}, …]} for every glTF node that places a mesh (id = node index + 1, what the
// npy and png16 files hold; the EXR channel holds the node index).
std::string instancesJson(const Scene& scene);

}  // namespace lenslab
