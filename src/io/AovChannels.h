#pragma once
// The AOVs (core/Aovs.h) as EXR channels, named as OpenEXR's conventions have them: depth is
// `Z` (OpenEXR's depth channel), the normal the layer `N` (`N.X`, `N.Y`, `N.Z`), the albedo the
// layer `albedo` (`albedo.R`, `albedo.G`, `albedo.B`), the instance `instance` (float: glTF node
// indices are exact integers in it up to 2^24).
#include "core/Aovs.h"
#include "io/ImageFile.h"

#include <string>
#include <vector>

namespace lenslab {

// The channel names the selection writes, in the order aovChannels gives them.
std::vector<std::string> aovChannelNames(const AovSelection& selection);

// The filled images as channels, in the order of aovChannelNames.
std::vector<ImageChannel> aovChannels(const AovImages& images);

}  // namespace lenslab
