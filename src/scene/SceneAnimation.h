#pragma once
// glTF node animation as pure data (GLM + std, no GL), and the pose of a Scene at a time.
//
// The loader flattens the node hierarchy into Scene::instances and Scene::cameras at rest; to
// re-pose them it keeps here what a pose needs and nothing more: the drawn nodes (parent, rest
// transform, which instances and cameras hang on each) and the channels that move them. Posing
// reads no file and allocates little: it is meant to be called once per frame.
//
// Each of the file's animations is a clip (glTF's "animation": a walk, a run, a survey). One clip
// plays at a time — by default the first, as viewers do; several clips posed at once mix their
// poses (a fox half walking, half running) — or all of them together on one clock.
//
// Conventions, as glTF has them: times in seconds from each clip's start (all on one clock when
// all play); a node's local transform is T * R * S (rotation a unit quaternion); before the first
// key a channel holds its first value, after the last its last value.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace lenslab {

struct Scene;

// A node of the drawn scene, as the loader placed it. Listed parents first (the placement order),
// so one pass down the list composes world transforms.
struct AnimatedNode {
  int parent = -1;    // index into SceneAnimation::nodes; -1 for a root of the drawn scene
  int gltfNode = -1;  // index in the file, for messages
  std::string name;   // the node's name in the file, may be empty
  // At rest: the node's local transform as the loader composed it (its matrix, or T * R * S).
  glm::dmat4 parentFromNodeAtRest{1.0};
  // Its T, R and S at rest (identity parts for a node given by a matrix, which glTF forbids
  // animating), the values that channels which do not drive a part leave in place.
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // GLM order: w, x, y, z
  glm::dvec3 scale{1.0};
  std::vector<int> instances;  // indices into Scene::instances placed by this node
  std::vector<int> cameras;    // indices into Scene::cameras placed by this node
  std::vector<int> lights;     // indices into Scene::lights placed by this node (KHR_lights_punctual)
};

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Step, Linear, CubicSpline };

// One animated property of one node: glTF's channel with its sampler's data.
struct AnimationChannel {
  int node = -1;  // index into SceneAnimation::nodes
  AnimationPath path = AnimationPath::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<double> keyTimesSeconds;  // strictly increasing, at least one
  // Per key: one value (Step, Linear) or three (CubicSpline: in-tangent, value, out-tangent, as
  // glTF stores them). Translation and scale use x, y, z; rotation is the quaternion x, y, z, w
  // in glTF's order.
  std::vector<glm::dvec4> values;
};

// One of the file's animations: its channels that move drawn nodes.
struct AnimationClip {
  std::string name;                        // the animation's name in the file, may be empty
  std::vector<AnimationChannel> channels;  // at most one per node and path; empty when it moves nothing drawn
  std::size_t fileChannelCount = 0;        // its channels in the file, played or not (what `info` lists)
};

// Which clips play: one, by its index in SceneAnimation::clips, or all of them together.
constexpr int kAllClips = -1;

struct SceneAnimation {
  std::vector<AnimatedNode> nodes;   // empty when no clip moves anything
  std::vector<AnimationClip> clips;  // every animation of the file, in the file's order
  int playing = 0;                   // index into clips, or kAllClips; poseScene plays these
  // True when what plays moves nothing (no clips, or the playing clip moves no drawn node).
  bool empty() const;
  // True when some clip, playing or not, moves a drawn node.
  bool anyClipMoves() const;
};

// The largest key time of a clip's channels (0 when it has none).
double clipDurationSeconds(const AnimationClip& clip);

// The duration of what plays: the playing clip's, or the longest clip's when all play; 0 when the
// scene is not animated.
double animationDurationSeconds(const Scene& scene);

// Moves the scene's instances and cameras to where the playing clip (or all clips, in the file's
// order: a later channel on the same node and path wins) puts them at `seconds`, and updates its
// bounds. A scene whose playing clips move nothing is left as it is. Throws InputError (one line:
// the scene file, the node, the time) when the pose is not finite or puts a vertex beyond
// ±kMaxWorldCoordinate; the scene then holds part of that pose until it is posed again.
void poseScene(Scene& scene, double seconds);

}  // namespace lenslab
