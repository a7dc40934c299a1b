#include "app/AovOption.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/AovChannels.h"

#include <algorithm>
#include <cctype>

namespace lenslab {

void addAovOption(CLI::App& command, std::vector<std::string>& names) {
  command
      .add_option("--aov", names,
                  "ground truth beside the image, as EXR channels (a list, e.g. depth,normal): depth = Z, the "
                  "distance from the lens centre along the optical axis (world units, +inf where nothing is hit); "
                  "normal = N.X N.Y N.Z, the shading normal in camera space (x right, y up, z toward the viewer); "
                  "albedo = albedo.R albedo.G albedo.B, the linear base colour; instance = the glTF node index "
                  "(-1 where nothing is hit). One ray per pixel centre from the lens centre (docs/capture.md)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(aovNames()))
      ->type_name("LIST");
}

void checkAovOutput(const AovSelection& selection, const std::filesystem::path& image, const std::string& outOption) {
  if (!selection.any()) return;
  std::string ext = image.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".exr") return;
  std::string channels;
  for (const std::string& c : aovChannelNames(selection)) channels += (channels.empty() ? "" : " ") + c;
  throw InputError(cat("--aov ", aovList(selection), ": ", image.string(), ": the AOVs go in an EXR's channels (",
                       channels, "); give an ", outOption, " ending in .exr"));
}

}  // namespace lenslab
