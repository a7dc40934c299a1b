#include "scene/gltf/Animations.h"

#include "scene/gltf/Problems.h"

#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace lenslab::gltf {

namespace {

Interpolation interpolationOf(const std::string& name, const std::string& where) {
  if (name == "STEP") return Interpolation::Step;
  if (name == "LINEAR") return Interpolation::Linear;
  if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
  refuse(where, ": interpolation \"", name, "\" is not one of STEP, LINEAR, CUBICSPLINE");
}

const char* pathName(AnimationPath path) {
  switch (path) {
    case AnimationPath::Translation: return "translation";
    case AnimationPath::Rotation: return "rotation";
    case AnimationPath::Scale: return "scale";
  }
  return "";
}

// glTF: key times are non-negative and strictly increasing (finite: the reader refuses others).
std::vector<double> readKeyTimes(const AccessorReader& reader, int accessor, const std::string& where) {
  const Elements e = reader.read(accessor);
  if (e.components != 1)
    refuse(where, ": its input (accessor ", accessor, ") holds ", e.components,
           "-component elements; key times are SCALAR");
  for (std::size_t k = 0; k < e.count; ++k) {
    if (e.values[k] < 0.0) refuse(where, ": key time ", k, " is ", e.values[k], " s; key times must not be negative");
    if (k > 0 && !(e.values[k] > e.values[k - 1]))
      refuse(where, ": key times must strictly increase (", e.values[k - 1], " s then ", e.values[k], " s at key ", k,
             ")");
  }
  return e.values;
}

// The output's elements as dvec4 (x, y, z, 0 for translation and scale; x, y, z, w for rotation).
std::vector<glm::dvec4> readValues(const AccessorReader& reader, int accessor, AnimationPath path, std::size_t count,
                                   const std::string& where) {
  const Elements e = reader.read(accessor);
  const std::size_t components = path == AnimationPath::Rotation ? 4 : 3;
  if (e.components != components)
    refuse(where, ": its output (accessor ", accessor, ") holds ", e.components, "-component elements; ",
           pathName(path), " needs VEC", components);
  if (e.count != count) refuse(where, ": its output holds ", e.count, " values; its key times need ", count);
  std::vector<glm::dvec4> values(e.count, glm::dvec4(0.0));
  for (std::size_t k = 0; k < e.count; ++k)
    for (std::size_t c = 0; c < components; ++c) values[k][static_cast<glm::length_t>(c)] = e.at(k, c);
  return values;
}

}  // namespace

void readAnimations(const tinygltf::Model& model, const AccessorReader& reader, const std::vector<int>& slotOfNode,
                    Scene& scene) {
  SceneAnimation& animation = scene.animation;
  std::size_t weights = 0, undrawn = 0, matrixNodes = 0;
  for (std::size_t i = 0; i < model.animations.size(); ++i) {
    const tinygltf::Animation& a = model.animations[i];
    AnimationClip clip;
    clip.name = a.name;
    clip.fileChannelCount = a.channels.size();
    std::map<std::pair<int, AnimationPath>, std::size_t> channelOf;  // (node slot, path) → index in clip.channels
    for (std::size_t c = 0; c < a.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = a.channels[c];
      const tinygltf::AnimationSampler& sampler =
          a.samplers[toIndex(channel.sampler)];  // indices checked by checkModel
      const std::string where = cat("animation ", i, " channel ", c);
      AnimationChannel out;
      out.interpolation = interpolationOf(sampler.interpolation, cat("animation ", i, " sampler ", channel.sampler));
      const std::string& path = channel.target_path;
      if (path == "weights") {
        ++weights;  // morph targets are not drawn, so neither are their weights played
        continue;
      }
      if (path == "translation")
        out.path = AnimationPath::Translation;
      else if (path == "rotation")
        out.path = AnimationPath::Rotation;
      else if (path == "scale")
        out.path = AnimationPath::Scale;
      else
        refuse(where, ": target path \"", path, "\" is not one of translation, rotation, scale, weights");
      // Every played path is read and checked, drawn or not: a broken file is refused whichever node it moves.
      out.keyTimesSeconds = readKeyTimes(reader, sampler.input, where);
      const std::size_t perKey = out.interpolation == Interpolation::CubicSpline ? 3 : 1;
      out.values = readValues(reader, sampler.output, out.path, perKey * out.keyTimesSeconds.size(), where);
      out.node = slotOfNode[toIndex(channel.target_node)];
      if (out.node < 0) {
        ++undrawn;
        continue;
      }
      if (model.nodes[toIndex(channel.target_node)].matrix.size() == 16) {
        ++matrixNodes;  // glTF: an animated node has no matrix; which would win is not defined
        continue;
      }
      // Within one clip glTF forbids two channels on one node and path; should a file have them,
      // the later plays. Across clips they are the norm (each clip moves the same bones).
      const auto key = std::make_pair(out.node, out.path);
      if (const auto found = channelOf.find(key); found != channelOf.end()) {
        noteOnce(scene.notes, cat(where, " drives the ", path, " of node ", channel.target_node,
                                  " that an earlier channel of the same animation drives too: the later one plays"));
        clip.channels[found->second] = std::move(out);
      } else {
        channelOf.emplace(key, clip.channels.size());
        clip.channels.push_back(std::move(out));
      }
    }
    animation.clips.push_back(std::move(clip));
  }
  if (weights > 0)
    noteOnce(scene.notes,
             cat(weights, " animation channel(s) drive morph target weights: not played (morph targets are ignored)"));
  if (undrawn > 0)
    noteOnce(scene.notes, cat(undrawn, " animation channel(s) move nodes outside the drawn scene: not played"));
  if (matrixNodes > 0)
    noteOnce(scene.notes,
             cat(matrixNodes,
                 " animation channel(s) target nodes given by a matrix, which glTF does not allow: not played"));
  animation.playing = 0;  // the first clip plays unless the user picks another (--animation)
  if (!animation.anyClipMoves()) {
    animation.nodes.clear();  // nothing moves: keep no copy of the hierarchy
    if (!model.animations.empty())
      noteOnce(scene.notes, cat(model.animations.size(),
                                " animation(s), none of which moves a drawn node: the scene is drawn at rest"));
    return;
  }
  noteOnce(scene.notes,
           cat(model.animations.size(),
               " animation(s) (`lenslab info` lists them): `render --time` and `capture` play the first, "
               "or the one --animation names (all: every one together); otherwise the rest pose is drawn"));
}

}  // namespace lenslab::gltf
