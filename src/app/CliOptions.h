#pragma once
// The command-line options that render, raycast, sweep and view share, registered with CLI11:
// aperture pattern, sample count, seed, focus (plan/UserOptions.h holds what they mean), the
// camera's lens, pose, glTF camera and animation clip (plan/CameraOptions.h), the animations'
// time, the background colour, and X,Y pairs.
#include "core/NumberInput.h"
#include "plan/CameraOptions.h"
#include "plan/UserOptions.h"

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include <functional>
#include <optional>
#include <string>

namespace lenslab {

// --pattern, --aperture-samples, --max-samples: the rasterizer's aperture sampling (render,
// capture, view; the ray caster has --spp instead).
void addSamplingOptions(CLI::App& command, LensOptions& options);
// --seed: the aperture and sub-pixel samples' (every command that samples).
void addSeedOption(CLI::App& command, LensOptions& options);
// --focus-distance, --focus-at (render, raycast, view; capture takes focus from its path).
void addFocusOptions(CLI::App& command, LensOptions& options);
// The lens over the camera's: --blades N and --squeeze RATIO (the aperture's shape,
// lens/ApertureShape.h), --distortion, --lateral-color and --axial-color (its effects,
// lens/LensEffects.h; plan/UserOptions.h withLensEffectOptions says how each replaces the camera's).
void addLensOverrideOptions(CLI::App& cmd, LensOptions& o);
// --target-psnr DB (render and view; sweep runs its adaptive method at several targets).
void addTargetOption(CLI::App& command, LensOptions& options);

// --focal-length, --f-number, --sensor, --eye, --target, --camera-node and --animation (render,
// raycast, view, capture): what they mean and how they compose with the camera is
// plan/CameraOptions.h. `withPose`: --eye and --target too; `withAnimation`: --animation too (sweep
// draws the rest pose).
void addCameraOptions(CLI::App& command, CameraOptions& options, bool withPose = true, bool withAnimation = true);
// --colmap DIR --image NAME: a COLMAP photograph's camera as the base (render, raycast, view).
void addColmapOptions(CLI::App& command, CameraOptions& options);
// --camera-node alone (info, sweep).
void addCameraNodeOption(CLI::App& command, CameraOptions& options);

// --time SECONDS: the glTF animations' pose for one image (render, raycast, view), -1e9 to 1e9;
// `description` is the command's help text for it.
void addTimeOption(CLI::App& command, std::optional<double>& seconds, const std::string& description);

// --background R,G,B: the colour (linear RGB, each finite, 0 to 65504) where no surface is seen.
void addBackgroundOption(CLI::App& command, std::optional<glm::vec3>& background);

// --lens FILE: a lens prescription (assets/lenses/; docs/lenses.md) that the command `fits` (render:
// with --lens-tolerance PX, the fit's largest error for the real-time path, 0 to 1e6, when
// `tolerancePx` is given) or traces (raycast, sweep); `description` says which.
void addLensFileOptions(CLI::App& command, std::string& file, const std::string& description,
                        double* tolerancePx = nullptr);

// Every number option's check (each value of a list option's): core/NumberInput's rules, so nan,
// inf and 1e309 are refused as not finite and the message names the option, the unit and the range.
// CLI11's Range is not used for floating-point options: nan passes it.
CLI::Validator numberIn(const NumberRange& range);
// As numberIn, also taking the word "infinity" (--focus-distance).
CLI::Validator numberOrInfinity(const NumberRange& range);

// An option that takes two numbers as X,Y (CLI11 splits and converts them), each in `range`
// (numberIn), e.g. --focus-at.
CLI::Option* addPairOption(CLI::App& command, const std::string& name, std::function<void(double, double)> set,
                           const std::string& description, const NumberRange& range);

}  // namespace lenslab
