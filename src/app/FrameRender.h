#pragma once
// One raster frame on a renderer that already holds the scene: what `render` does for an image
// that fits one render target, and what `capture` does for every frame of a path — one code path,
// so that `render` with a frame's camera file and seed gives that frame's pixels.
#include "app/Stats.h"
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "io/ImageFile.h"
#include "io/Progress.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/Scene.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace lenslab {

// The plan, from a pinhole depth pre-pass when it chooses a count or renders to a target error.
// Sets stats.plan and stats.prepassSeconds; the plan's warnings are left to the caller.
FramePlan planFrame(Renderer& renderer, const Scene& scene, const Camera& camera, ImageSize size,
                    const PlanOptions& options, RunStats& stats);

// Renders `plan` (not tiled): its fixed count in batches, or per-tile rounds to the target error.
// Progress to `progress` when given and not silent (the lens tables, then samples; tiles at the
// target with a target error; the caller finishes it); the warning that a target was not met
// unless `quiet`.
// Sets stats.estimate (with a target).
Image renderPlanned(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, RunStats& stats,
                    ProgressReporter* progress, bool quiet);

// The image made ready for `path` (io/ImageFile.h's applyDisplayForFile), after one warning line
// on `warnings` ("lenslab: warning: <where>…") if its radiance ran past a float's range.
void prepareForFile(const std::filesystem::path& path, Image& image, const DisplayEncoding& display,
                    const std::string& where, std::ostream& warnings);

}  // namespace lenslab
