#include "scene/SceneAnimation.h"

#include "core/Error.h"
#include "core/Text.h"
#include "scene/Scene.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>

namespace lenslab {

namespace {

std::size_t toIndex(int index) { return static_cast<std::size_t>(index); }

glm::dquat toQuat(const glm::dvec4& xyzw) { return glm::dquat(xyzw.w, xyzw.x, xyzw.y, xyzw.z); }
glm::dvec4 toXyzw(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }

// Spherical linear interpolation the short way round (q and -q are the same rotation), falling
// back to a normalised lerp where the two are so close that sin(angle) loses its digits.
glm::dvec4 slerp(glm::dvec4 a, glm::dvec4 b, double u) {
  a = glm::normalize(a);
  b = glm::normalize(b);
  double cosAngle = glm::dot(a, b);
  if (cosAngle < 0.0) {
    b = -b;
    cosAngle = -cosAngle;
  }
  if (cosAngle > 1.0 - 1e-9) return glm::normalize(glm::mix(a, b, u));
  const double angle = std::acos(cosAngle);
  return (std::sin((1.0 - u) * angle) * a + std::sin(u * angle) * b) / std::sin(angle);
}

// glTF's cubic Hermite spline between keys k and k+1 at u in [0, 1]; the stored tangents are per
// second, so they are scaled by the key interval (the spec's (t_{k+1} - t_k) * b_k and * a_{k+1}).
glm::dvec4 hermite(const AnimationChannel& c, std::size_t k, double u) {
  const double intervalSeconds = c.keyTimesSeconds[k + 1] - c.keyTimesSeconds[k];
  const glm::dvec4& p0 = c.values[3 * k + 1];
  const glm::dvec4 m0 = intervalSeconds * c.values[3 * k + 2];  // out-tangent of key k
  const glm::dvec4& p1 = c.values[3 * (k + 1) + 1];
  const glm::dvec4 m1 = intervalSeconds * c.values[3 * (k + 1)];  // in-tangent of key k+1
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1;
}

// The channel's value at `seconds`: x, y, z (translation, scale) or a unit quaternion x, y, z, w.
glm::dvec4 sample(const AnimationChannel& c, double seconds) {
  const std::vector<double>& t = c.keyTimesSeconds;
  assert(!t.empty());
  const std::size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
  const std::size_t valueOffset = c.interpolation == Interpolation::CubicSpline ? 1 : 0;  // skip the in-tangent
  const auto keyValue = [&](std::size_t k) { return c.values[perKey * k + valueOffset]; };
  glm::dvec4 v;
  if (!(seconds > t.front())) {  // NaN clamps to the first key too
    v = keyValue(0);
  } else if (seconds >= t.back()) {
    v = keyValue(t.size() - 1);
  } else {
    // t[k] <= seconds < t[k+1]: a time exactly at a key is that key's (STEP switches there).
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), seconds) - t.begin()) - 1;
    const double u = (seconds - t[k]) / (t[k + 1] - t[k]);
    switch (c.interpolation) {
      case Interpolation::Step: v = keyValue(k); break;
      case Interpolation::Linear:
        v = c.path == AnimationPath::Rotation ? slerp(keyValue(k), keyValue(k + 1), u)
                                              : glm::mix(keyValue(k), keyValue(k + 1), u);
        break;
      case Interpolation::CubicSpline: v = hermite(c, k, u); break;
    }
  }
  // Writers round their quaternions and splines leave the unit sphere: rotate, never shear.
  return c.path == AnimationPath::Rotation ? toXyzw(glm::normalize(toQuat(v))) : v;
}

glm::dmat4 composeTrs(const glm::dvec3& t, const glm::dquat& r, const glm::dvec3& s) {
  glm::dmat4 m = glm::mat4_cast(r);
  m[0] *= s.x;
  m[1] *= s.y;
  m[2] *= s.z;
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

bool finite(const glm::dmat4& m) {
  for (int i = 0; i < 16; ++i)
    if (!std::isfinite(glm::value_ptr(m)[i])) return false;
  return true;
}

std::string nodeName(const AnimatedNode& node) {
  return node.name.empty() ? cat("node ", node.gltfNode) : cat("node ", node.gltfNode, " (", node.name, ")");
}

// The first vertex beyond ±kMaxWorldCoordinate, searched only when the bounds say there is one.
void refuseFarVertices(const Scene& scene, double seconds) {
  const auto within = [](const glm::dvec3& p) {
    return glm::all(glm::lessThanEqual(glm::abs(p), glm::dvec3(kMaxWorldCoordinate)));
  };
  if (scene.bounds.empty() || (within(scene.bounds.min) && within(scene.bounds.max))) return;
  for (const AnimatedNode& node : scene.animation.nodes)
    for (const int i : node.instances) {
      const Instance& instance = scene.instances[toIndex(i)];
      for (const Vertex& v : scene.meshes[toIndex(instance.mesh)].vertices) {
        const glm::dvec3 p(instance.worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0));
        if (!within(p))
          throw InputError(
              cat(scene.source, ": at ", seconds, " s the animation moves ", nodeName(node),
                  " so that a vertex lies at (", p.x, ", ", p.y, ", ", p.z, "), beyond +-", kMaxWorldCoordinate,
                  " where lenslab keeps its precision; capture a shorter time range or fix the animation"));
      }
    }
}

// A KHR_lights_punctual light follows its node: it sits at the node's origin and shines along its −Z.
void placeLight(const Scene& scene, PunctualLight& light, const glm::dmat4& worldFromNode, const AnimatedNode& node,
                double seconds) {
  light.worldPosition = glm::dvec3(worldFromNode[3]);
  const glm::dvec3 shines(worldFromNode * glm::dvec4(0.0, 0.0, -1.0, 0.0));
  const double length = glm::length(shines);
  if (length > 0.0 && std::isfinite(length)) {
    light.worldDirection = shines / length;
  } else if (light.type != LightType::Point) {
    // A point light shines every way; the others need a direction, as the loader required at rest.
    throw InputError(
        cat(scene.source, ": at ", seconds, " s the animation scales ", nodeName(node),
            "'s -Z to nothing, so its light has no direction; capture a shorter time range or fix the animation"));
  }
}

}  // namespace

bool SceneAnimation::anyClipMoves() const {
  return std::any_of(clips.begin(), clips.end(), [](const AnimationClip& clip) { return !clip.channels.empty(); });
}

bool SceneAnimation::empty() const {
  if (playing == kAllClips) return !anyClipMoves();
  return playing < 0 || static_cast<std::size_t>(playing) >= clips.size() || clips[toIndex(playing)].channels.empty();
}

double clipDurationSeconds(const AnimationClip& clip) {
  double seconds = 0.0;
  for (const AnimationChannel& c : clip.channels) seconds = std::max(seconds, c.keyTimesSeconds.back());
  return seconds;
}

double animationDurationSeconds(const Scene& scene) {
  const SceneAnimation& animation = scene.animation;
  if (animation.empty()) return 0.0;
  if (animation.playing != kAllClips) return clipDurationSeconds(animation.clips[toIndex(animation.playing)]);
  double seconds = 0.0;
  for (const AnimationClip& clip : animation.clips) seconds = std::max(seconds, clipDurationSeconds(clip));
  return seconds;
}

void poseScene(Scene& scene, double seconds) {
  SceneAnimation& animation = scene.animation;
  if (animation.empty()) return;
  // Each node's T, R, S at this time: the rest values, overwritten by the channels that drive them.
  struct Trs {
    glm::dvec3 t;
    glm::dquat r;
    glm::dvec3 s;
    bool animated = false;
  };
  std::vector<Trs> trs(animation.nodes.size());
  for (std::size_t i = 0; i < animation.nodes.size(); ++i)
    trs[i] = {animation.nodes[i].translation, animation.nodes[i].rotation, animation.nodes[i].scale, false};
  // All clips: in the file's order, so that a later channel on the same node and path wins.
  const std::size_t first = animation.playing == kAllClips ? 0 : toIndex(animation.playing);
  const std::size_t last = animation.playing == kAllClips ? animation.clips.size() : first + 1;
  for (std::size_t k = first; k < last; ++k)
    for (const AnimationChannel& c : animation.clips[k].channels) {
      Trs& node = trs[toIndex(c.node)];
      const glm::dvec4 v = sample(c, seconds);
      switch (c.path) {
        case AnimationPath::Translation: node.t = glm::dvec3(v); break;
        case AnimationPath::Rotation: node.r = toQuat(v); break;
        case AnimationPath::Scale: node.s = glm::dvec3(v); break;
      }
      node.animated = true;
    }
  // Down the hierarchy (parents come first), in double precision as the loader composes.
  std::vector<glm::dmat4> worldFromNode(animation.nodes.size());
  for (std::size_t i = 0; i < animation.nodes.size(); ++i) {
    const AnimatedNode& node = animation.nodes[i];
    const glm::dmat4 parentFromNode =
        trs[i].animated ? composeTrs(trs[i].t, trs[i].r, trs[i].s) : node.parentFromNodeAtRest;
    assert(node.parent < static_cast<int>(i));
    worldFromNode[i] = node.parent >= 0 ? worldFromNode[toIndex(node.parent)] * parentFromNode : parentFromNode;
    if (!finite(worldFromNode[i]))
      throw InputError(cat(scene.source, ": at ", seconds, " s the animation gives ", nodeName(node),
                           " a world transform that is not finite; capture a shorter time range or fix the animation"));
    for (const int k : node.instances) scene.instances[toIndex(k)].worldFromModel = worldFromNode[i];
    for (const int k : node.cameras) scene.cameras[toIndex(k)].worldFromCamera = worldFromNode[i];
    for (const int k : node.lights) placeLight(scene, scene.lights[toIndex(k)], worldFromNode[i], node, seconds);
  }
  scene.bounds = computeBounds(scene);
  refuseFarVertices(scene, seconds);
}

}  // namespace lenslab
