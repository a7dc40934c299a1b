#include "app/Stats.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace lenslab {

void RunStats::setCamera(const SelectedCamera& selected) {
  camera = selected.camera.source;
  focusDistance = selected.camera.focusDistance();
  apertureRadius = selected.camera.lens.apertureRadius;
  aperture = selected.camera.lens.aperture;
  barrel = selected.camera.lens.barrel;
  physical = selected.physical;
}

void RunStats::setCamera(const SelectedCamera& fitted, const FocusExplanation& focus) {
  setCamera(fitted);
  askedFocusDistance = focus.askedDistance;
  focusNote = focus.note;
}

namespace {

nlohmann::json distanceJson(double d) { return std::isinf(d) ? nlohmann::json("infinity") : nlohmann::json(d); }

// The camera's lens: focus, aperture and its shape, the barrel, and the physical camera it came from.
nlohmann::json lensJson(const RunStats& s) {
  nlohmann::json j = {{"focus_distance", distanceJson(s.focusDistance)},
                      {"aperture_radius", s.apertureRadius},
                      {"aperture",
                       {{"shape", describeAperture(s.aperture)},
                        {"blades", s.aperture.blades},
                        {"rotation_deg", s.aperture.rotationDeg},
                        {"roundness", s.aperture.roundness},
                        {"anamorphic_squeeze", s.aperture.anamorphicSqueeze}}}};
  if (s.barrel.present()) j["barrel"] = {{"distance", s.barrel.distance}, {"radius", s.barrel.radius}};
  if (s.askedFocusDistance) j["asked_focus_distance"] = distanceJson(*s.askedFocusDistance);
  if (!s.focusNote.empty()) j["focus_note"] = s.focusNote;
  if (s.physical) {
    const PhysicalCamera& p = *s.physical;
    j["focal_length_mm"] = p.focalLengthMm;
    j["f_number"] = distanceJson(p.fNumber);
    j["sensor_mm"] = {p.sensorMm.x, p.sensorMm.y};
    j["eye"] = {p.eye.x, p.eye.y, p.eye.z};
    j["target"] = {p.target.x, p.target.y, p.target.z};
  }
  return j;
}

// The exposure and view transform of PNG output (and of the viewer's display); EXR output holds
// the radiance before them.
nlohmann::json displayJson(const RunStats& s) {
  const Exposure& e = s.exposure;
  nlohmann::json d = {{"exposure_stops", e.stops},
                      {"exposure_scale", e.scale},
                      {"exposure_source", e.source},
                      {"exposure", describe(e)},
                      {"view_transform", viewTransformName(s.viewTransform)}};
  if (e.ev100) {
    d["ev100"] = *e.ev100;
    d["shutter_s"] = *e.shutterSeconds;
    d["iso"] = *e.iso;
    d["f_number"] = *e.fNumber;
  }
  // The EV100 whose scale the PNG got, the frame's meter reading beside it (null: no light to
  // meter; absent: not metered, as for a tiled render), the camera's own where it has one.
  d["used_ev100"] = ev100ForScale(e.scale);
  if (e.meterReading) {
    d["metered_ev100"] = e.meterReading->ev100 ? nlohmann::json(*e.meterReading->ev100) : nlohmann::json();
    d["metering"] =
        "centre-weighted geometric mean luminance, 75 % from the central circle (half the shorter side across); "
        "EV100 = log2(L * 100 / 12.5)";
  }
  if (e.cameraEv100) d["camera_ev100"] = *e.cameraEv100;
  return d;
}

// The frame plan: its passes with why, the aperture samples and the blur they were chosen for.
nlohmann::json planJson(const FramePlan& plan) {
  nlohmann::json passes = nlohmann::json::array();
  for (const PlannedPass& p : plan.passes)
    passes.push_back({{"name", p.name}, {"why", p.why}, {"variants", p.variants}});
  nlohmann::json j = {{"passes", passes},
                      {"aperture_samples", plan.apertureSamples},
                      {"aperture_samples_why", plan.samplesWhy},
                      {"pattern", patternName(plan.pattern)},
                      {"cell_filter", plan.cellFilterWhy},
                      {"seed", plan.seed},
                      {"coc_px", {{"min", plan.cocMinPx}, {"max", plan.cocMaxPx}}},
                      {"depth_range", {{"min", plan.depthMin}, {"max", distanceJson(plan.depthMax)}}},
                      {"views_per_sample", plan.viewsPerSample},
                      {"render_size", {plan.overscan.size.widthPx, plan.overscan.size.heightPx}}};
  if (plan.visible) {
    const VisibleBlurSummary& v = *plan.visible;
    j["visible_blur"] = {
        {"prepass_size", {v.prepass.widthPx, v.prepass.heightPx}},
        {"fraction_of_pixels",
         {{"coc_le_1px", v.fractions[0]},
          {"coc_1_to_4px", v.fractions[1]},
          {"coc_4_to_16px", v.fractions[2]},
          {"coc_16_to_64px", v.fractions[3]},
          {"coc_over_64px", v.fractions[4]}}},
        {"coc_px_percentiles", {{"p50", v.p50Px}, {"p90", v.p90Px}, {"p99", v.p99Px}, {"max", v.maxPx}}},
        {"bounds_coc_max_px", v.boundsCocMaxPx},
        {"bounds_aperture_samples", v.boundsSamples}};
  }
  if (plan.adaptive) {
    j["target_psnr"] = plan.adaptive->targetPsnrDb;
    j["tile_size"] = plan.adaptive->tileSizePx;
  }
  return j;
}

}  // namespace

std::string toJson(const RunStats& s) {
  nlohmann::json j;
  j["command"] = s.command;
  j["scene"] = s.scene;
  j["camera"] = s.camera;
  j["lens"] = lensJson(s);
  j["display"] = displayJson(s);
  if (s.environment) {
    const EnvironmentSummary& e = *s.environment;
    j["environment"] = {{"file", e.file},
                        {"intensity", e.intensity},
                        {"rotation_deg", e.rotationDegrees},
                        {"width", e.widthPx},
                        {"height", e.heightPx},
                        {"specular_levels", e.specularLevels},
                        {"from_cache", e.fromCache},
                        {"load_seconds", e.seconds}};
  }
  j["width"] = s.size.widthPx;
  j["height"] = s.size.heightPx;
  j["backend"] = s.backend;
  j["renderer"] = s.renderer;
  j["triangles"] = s.triangles;
  j["seconds"] = s.seconds;
  j["timings"] = {{"context_seconds", s.contextSeconds},
                  {"setup_seconds", s.setupSeconds},
                  {"render_seconds", s.renderSeconds},
                  {"write_seconds", s.writeSeconds},
                  {"prepass_seconds", s.prepassSeconds}};
  j["plan"] = planJson(s.plan);
  if (s.estimate) {
    const FrameEstimate& e = *s.estimate;
    j["estimate"] = {{"psnr", e.psnrDb},
                     {"rmse", e.rmse},
                     {"target_met", e.targetMet},
                     {"against", "the image's own converged limit (two independent sample streams)"}};
    j["samples"] = {{"min", e.minSamples}, {"mean", e.meanSamples},
                    {"max", e.maxSamples}, {"tiles", e.tiles},
                    {"rounds", e.rounds},  {"allocation", e.wholeFrame ? "uniform" : "per tile"}};
  }
  return j.dump(2) + "\n";
}

void writeStats(OutputSet& outputs, const std::filesystem::path& path, const RunStats& stats) {
  outputs.add(path, toJson(stats));
}

}  // namespace lenslab
