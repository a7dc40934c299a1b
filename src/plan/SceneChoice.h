#pragma once
// What --camera-node and --animation pick from a scene: a glTF camera or an animation clip, by
// index (as `info` lists them) or by name, refused in one line that lists what the scene has;
// and the scene posed for one image (--animation, --time). Pure (no GL, no command-line library).
#include "scene/Scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// How a glTF camera is named in messages and `info`: its index, node name and camera name.
std::string sceneCameraLabel(const Scene& scene, std::size_t index);
// The index in scene.cameras of --camera-node's value: a whole number is an index (as `info` lists
// them), else a node name, else a camera name. Throws InputError listing the cameras when none (or
// more than one) matches.
std::size_t findSceneCamera(const Scene& scene, const std::string& nameOrIndex);

// Makes --animation's clip the one poseScene plays (a name, an index as `info` lists them, or all);
// empty leaves the default (the first). Throws InputError listing the clips.
void selectAnimation(Scene& scene, const std::string& nameIndexOrAll);

// --animation and --time for one image (render, raycast, view): selects the clip and poses the
// scene at the time. Returns what the user should hear: a time on a scene whose playing clip moves
// nothing, a clip without a time (the rest pose is drawn).
std::vector<std::string> poseForOneImage(Scene& scene, const std::string& animation, std::optional<double> timeSeconds);

}  // namespace lenslab
