#include "plan/SceneChoice.h"

#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>

namespace lenslab {
namespace {

[[noreturn]] void refuse(const std::string& option, const std::string& why) {
  throw InputError(cat(option, ": ", why));
}

bool isWholeNumber(const std::string& text) {
  return !text.empty() && text.size() < 10 &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// One kind of name a choice can be picked by, and each choice's name of that kind.
struct NameKind {
  std::string what;  // for refusals: "node name"
  std::vector<std::string> names;
};

// What --camera-node and --animation pick from, as their refusals name it.
struct Choices {
  std::string source;           // the scene file
  std::string noun;             // "camera": refusals say "camera(s)", "2 cameras of ..."
  std::string list;             // every choice as `info` lists it
  std::vector<NameKind> kinds;  // tried in order; each holds one name per choice
  std::string anyName;          // how "no ... has that ..." names all the kinds: "node or camera name"
};

// The choice `text` picks: a whole number is an index (as `info` lists them), else a name, tried
// kind by kind (a camera's node name before its camera name): the first kind in which some choice
// has it decides, and exactly one must. Refuses `option`, listing the choices, when the index is
// beyond them or the name is no choice's or several's.
std::size_t pickChoice(const Choices& c, const std::string& option, const std::string& text) {
  const std::size_t count = c.kinds.front().names.size();
  if (isWholeNumber(text)) {
    const std::size_t index = std::stoul(text);
    if (index < count) return index;
    refuse(option, cat(c.source, " has ", count, " ", c.noun, "(s): ", c.list));
  }
  for (const NameKind& kind : c.kinds) {
    std::vector<std::size_t> matches;
    for (std::size_t i = 0; i < count; ++i)
      if (kind.names[i] == text) matches.push_back(i);
    if (matches.size() == 1) return matches.front();
    if (matches.size() > 1)
      refuse(option, cat(matches.size(), " ", c.noun, "s of ", c.source, " have that ", kind.what,
                         "; give an index: ", c.list));
  }
  refuse(option, cat("no ", c.noun, " of ", c.source, " has that ", c.anyName, "; it has ", c.list));
}

}  // namespace

std::string sceneCameraLabel(const Scene& scene, std::size_t index) {
  const SceneCamera& c = scene.cameras[index];
  std::string label = cat("[", index, "] ");
  label += c.nodeName.empty() ? cat("node ", c.gltfNode) : cat("node \"", c.nodeName, "\"");
  if (!c.name.empty() && c.name != c.nodeName) label += cat(" (camera \"", c.name, "\")");
  return label;
}

std::size_t findSceneCamera(const Scene& scene, const std::string& text) {
  const std::string option = cat("--camera-node ", text);
  if (scene.cameras.empty())
    refuse(option,
           cat(scene.source, " has no cameras; leave the option out for the automatic framing, or give --camera FILE"));
  Choices cameras{scene.source, "camera", "", {{"node name", {}}, {"camera name", {}}}, "node or camera name"};
  for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
    cameras.list += (i ? ", " : "") + sceneCameraLabel(scene, i);
    cameras.kinds[0].names.push_back(scene.cameras[i].nodeName);
    cameras.kinds[1].names.push_back(scene.cameras[i].name);
  }
  return pickChoice(cameras, option, text);
}

void selectAnimation(Scene& scene, const std::string& text) {
  if (text.empty()) return;
  SceneAnimation& animation = scene.animation;
  const std::string option = cat("--animation ", text);
  if (animation.clips.empty()) refuse(option, cat(scene.source, " has no animations"));
  if (text == "all") {
    animation.playing = kAllClips;
    return;
  }
  Choices clips{scene.source, "animation", "", {{"name", {}}}, "name"};
  for (std::size_t i = 0; i < animation.clips.size(); ++i) {
    const std::string& name = animation.clips[i].name;
    clips.list += cat(i ? ", " : "", "[", i, "]", name.empty() ? "" : cat(" \"", name, "\""));
    clips.kinds[0].names.push_back(name);
  }
  clips.list += ", or all";
  animation.playing = static_cast<int>(pickChoice(clips, option, text));
}

std::vector<std::string> poseForOneImage(Scene& scene, const std::string& animation,
                                         std::optional<double> timeSeconds) {
  selectAnimation(scene, animation);
  std::vector<std::string> warnings;
  if (timeSeconds) {
    if (scene.animation.empty())
      warnings.push_back(cat("--time ", *timeSeconds, ": ", scene.source,
                             scene.animation.clips.empty()
                                 ? " has no animation that moves what it draws"
                                 : "'s playing animation moves nothing it draws (--animation chooses another)"));
    poseScene(scene, *timeSeconds);
  } else if (!animation.empty()) {
    warnings.push_back(cat("--animation ", animation,
                           ": without --time the rest pose is drawn; give --time SECONDS to pose the scene"));
  }
  return warnings;
}

}  // namespace lenslab
