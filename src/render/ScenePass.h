#pragma once
// The scene pass: every instance drawn once with the camera's clipFromWorld, into a float colour
// target with reverse-Z depth (clear to 0, GREATER). One pass is one view from one PRP.
//
// A narrow field of view (window under 1/kNarrowFieldSlope of the PRP's distance, about 2e-3 rad)
// is drawn by shaders/scene/narrow_field.*: positions in double, each triangle clipped in double
// to twice the image before GL's float takes over. In float alone a vertex 1e8 window widths
// off-axis has no digit left for where its triangle crosses the image (a sky stripe across a
// uniform floor at 1e-7 rad).
//
// Surfaces of alphaMode BLEND are drawn after the opaque ones and the background, back to front
// (scene/BlendOrder.h), depth tested but not written, blended `over` (drawBlended). They are
// drawn only into a view of its own: a scene with any is never added into a sum (addWeight;
// Renderer draws its views into layers).
#include "gl/Framebuffer.h"
#include "gl/Object.h"
#include "plan/TileBudget.h"
#include "render/GpuEnvironment.h"
#include "render/GpuScene.h"
#include "render/SceneUniforms.h"

#include <glm/glm.hpp>

#include <memory>
#include <optional>

namespace lenslab {

// PRP distance over window size (about 1 / field of view) from which the scene pass clips in double.
constexpr double kNarrowFieldSlope = 1e3;

// Whether a perspective clipFromWorld has a field of view narrow enough for the double path.
bool isNarrowField(const glm::dmat4& clipFromWorld);

class ScenePass {
 public:
  ScenePass();  // builds the program (needs a current context)
  // `lodBias` is added to the textures' level of detail: −½·log2 N when this view is one of N
  // sub-pixel-jittered views of a pixel (scene.frag says why).
  // `boxes`: when given, only those rectangles of the target are cleared and drawn (per-tile
  // budgets: later views only where tiles still need them), one scissored pass each.
  // `addWeight`: when given, the view is added into the target's colour (a running sum,
  // render/Accumulator) with this weight per channel and alpha, instead of replacing it; see drawAdded.
  // A scene with alphaMode BLEND materials takes no addWeight (std::logic_error).
  void draw(const GpuScene& scene, const glm::dmat4& clipFromWorld, const gl::DrawTarget& target, float lodBias = 0.0f,
            const std::vector<PixelBox>* boxes = nullptr, const glm::vec4* addWeight = nullptr) const;

 private:
  // The programs of one way of drawing: opaque materials and alpha-masked ones (whose discard
  // stops llvmpipe testing depth before shading, so opaque ones are kept apart where it matters).
  struct Programs {
    GLuint opaque = 0;
    GLuint masked = 0;
  };
  // Adds the view into the target's colour without a layer of its own: a depth-only pass finds
  // each pixel's visible surface, then a colour pass adds (weight · (colour − background), weight.a)
  // where depth is EQUAL, and the stencil lets only the first such fragment add (two surfaces at
  // the same depth add once, as GREATER keeps the first in a plain pass). The caller has set depth
  // to far and stencil to 0 where the view may add, and adds weight · background itself.
  void drawAdded(const GpuScene& scene, const glm::dmat4& clipFromWorld, bool narrow, const glm::vec4& weight,
                 float lodBias) const;
  // `withMaps`: the same programs in their MATERIAL_MAPS variant, for materials that need it
  // (materialMaps below); unbuilt (0) when no material of the scene does.
  // `only`: these instances (indices into the scene's), in this order; null: every instance
  // whose material is not alphaMode BLEND, in the scene's order.
  void drawInstances(Programs programs, Programs withMaps, bool narrow, const GpuScene& scene,
                     const glm::dmat4& clipFromWorld, const std::vector<std::size_t>* only = nullptr) const;
  // The BLEND instances `backToFront` over what the view has drawn: depth GREATER without writes,
  // colour SRC_ALPHA, ONE_MINUS_SRC_ALPHA and alpha ONE, ONE_MINUS_SRC_ALPHA, so that alpha stays
  // the coverage (1 − Π(1 − alpha) over the background, as the ray caster's). Programs: the
  // ALPHA_BLEND variant (and its MATERIAL_MAPS one), built on first use.
  void drawBlended(const GpuScene& scene, const glm::dmat4& clipFromWorld, bool narrow, float lodBias,
                   const std::vector<std::size_t>& backToFront) const;
  // `slot`'s program, built first if empty: scene.vert for a wide field, narrow_field.vert and
  // .geom for a narrow one (both with scene.frag), with `defines` plus withVariant's.
  GLuint buildSceneProgram(gl::Program& slot, bool narrow, const std::vector<std::string>& defines) const;
  // The variant with `define` (DEPTH_ONLY, ADD_TO_SUM), built on first use.
  Programs variant(const char* define, bool narrow) const;
  // The MATERIAL_MAPS variant (normal map, TEXCOORD_1, uv transforms) of the plain program
  // (`define` null) or of variant(define), built on first use, with the lighting set.
  Programs mapsVariant(const char* define, bool narrow, const Scene& scene, float lodBias) const;
  void setLighting(GLuint program, const Scene& scene, float lodBias) const;
  // The shading origin of the view drawn now: its eye (its projection centre), or for a parallel
  // view the scene's centre and the direction toward the viewer.
  void placeShadingOrigin(const Scene& scene, const glm::dmat4& clipFromWorld) const;
  // The scene's environment on the GPU (uploaded on first use), or null when it has none. With
  // one, every view draws it behind its surfaces, each with its own directions (GpuEnvironment).
  const GpuEnvironment* environment(const Scene& scene) const;
  // An added view's background: weight · environment where its depth pass left no surface.
  void drawAddedBackground(const GpuEnvironment& environment, const glm::dmat4& clipFromWorld,
                           const gl::DrawTarget& target, const glm::vec4& weight) const;

  // Builds the programs for the scene's lighting: every scene program is compiled with
  // ENVIRONMENT where the scene has one (and without its lookups where it has none: llvmpipe runs
  // a branch's code even when no pixel takes it), and with LIGHT_COUNT, its number of punctual
  // lights, as a constant (a loop of known length costs llvmpipe less than one bounded by a
  // uniform). Changing either drops the programs built so far.
  void selectPrograms(bool environment, int lightCount) const;
  std::vector<std::string> withVariant(std::vector<std::string> defines) const;

  mutable gl::Program program_;
  mutable bool environmentVariant_ = false;  // what the programs below were built for
  mutable int lightCountVariant_ = -1;
  gl::Texture dfgTable_;               // scene/Brdf.h's table, RGB32F
  mutable ShadingView shadingView_;    // the view drawn now (placeShadingOrigin)
  mutable gl::Program narrowProgram_;  // built on first use: needs fp64 shaders
  // Built on first use: [narrow][DEPTH_ONLY, DEPTH_ONLY + ALPHA_MASK, ADD_TO_SUM].
  mutable gl::Program addPrograms_[2][3];
  // MATERIAL_MAPS programs, built on first use: [narrow][plain, DEPTH_ONLY, DEPTH_ONLY + ALPHA_MASK, ADD_TO_SUM].
  mutable gl::Program mapsPrograms_[2][4];
  // ALPHA_BLEND programs, built on first use: [narrow][plain, MATERIAL_MAPS].
  mutable gl::Program blendPrograms_[2][2];
  mutable std::unique_ptr<GpuEnvironment> environment_;
  // What environment_ was made from, held so that its address cannot be reused by another.
  mutable std::shared_ptr<const EnvironmentLookup> environmentSource_;
};

// Whether a material needs scene.frag's MATERIAL_MAPS variant: a normal, metallic-roughness or
// occlusion map, or a texture that samples TEXCOORD_1 or has a uv transform. Materials without
// keep the plain program, which carries no tangent, no second uv set, no transform and no
// lookups of those maps (docs/materials.md).
bool materialMaps(const Material& material);

}  // namespace lenslab
