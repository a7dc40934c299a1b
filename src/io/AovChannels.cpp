#include "io/AovChannels.h"

#include <cstddef>

namespace lenslab {

namespace {

const std::vector<std::string> kNormal{"N.X", "N.Y", "N.Z"};
const std::vector<std::string> kAlbedo{"albedo.R", "albedo.G", "albedo.B"};

// Component k of each pixel of an image of `count` values a pixel.
std::vector<float> component(const std::vector<float>& values, std::size_t count, std::size_t k) {
  std::vector<float> out(values.size() / count);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = values[i * count + k];
  return out;
}

}  // namespace

std::vector<std::string> aovChannelNames(const AovSelection& selection) {
  std::vector<std::string> names;
  if (selection.depth) names.push_back("Z");
  if (selection.normal) names.insert(names.end(), kNormal.begin(), kNormal.end());
  if (selection.albedo) names.insert(names.end(), kAlbedo.begin(), kAlbedo.end());
  if (selection.instance) names.push_back("instance");
  if (selection.flow) names.insert(names.end(), {"flow.X", "flow.Y"});
  return names;
}

std::vector<ImageChannel> aovChannels(const AovImages& images) {
  std::vector<ImageChannel> channels;
  if (!images.depth.empty()) channels.push_back({"Z", images.depth});
  if (!images.normal.empty())
    for (std::size_t k = 0; k < 3; ++k) channels.push_back({kNormal[k], component(images.normal, 3, k)});
  if (!images.albedo.empty())
    for (std::size_t k = 0; k < 3; ++k) channels.push_back({kAlbedo[k], component(images.albedo, 3, k)});
  if (!images.instance.empty()) channels.push_back({"instance", images.instance});
  if (!images.flow.empty())
    for (std::size_t k = 0; k < 2; ++k)
      channels.push_back({k == 0 ? "flow.X" : "flow.Y", component(images.flow, 2, k)});
  return channels;
}

}  // namespace lenslab
