// lenslab lens: what a lens prescription amounts to, for a sensor and a focus distance.
#include "app/CliOptions.h"
#include "app/Commands.h"
#include "app/LensPlot.h"
#include "io/AtomicFile.h"
#include "io/OutputPath.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "lens/LensAnalysis.h"
#include "lens/LensFit.h"
#include "lens/ParaxialLens.h"
#include "lens/LensPrescription.h"
#include "plan/CameraOptions.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

struct LensCommandOptions {
  std::string file;
  std::string sensor = "36x24";
  std::string focus = "infinity";
  std::optional<double> fNumber;
  bool json = false;
  std::string plot;
};

// The focus distance from the entrance pupil (LensFit's, the renderers') for the report's from the film.
double focusFromEntrancePupilMm(const LensPrescription& lens, const LensReport& r, const LensAnalysisOptions& o) {
  if (!(o.focusDistanceMm > 0.0) || std::isinf(o.focusDistanceMm)) return INFINITY;
  return o.focusDistanceMm - (lens.lengthMm() + r.filmDistanceMm - r.firstOrder.entrancePupilMm);
}

nlohmann::json fitJson(const FittedLens& fit) {
  if (!fit.usable) return {{"usable", false}, {"why", fit.why}};
  const LensFitError& e = fit.error;
  return {
      {"usable", true},
      {"focal_length_mm", fit.focalLengthMm},
      {"entrance_pupil_diameter_mm", fit.entrancePupilDiameterMm},
      {"focus_distance_mm",
       fit.inverseFocusPerMm > 0.0 ? nlohmann::json(1.0 / fit.inverseFocusPerMm) : nlohmann::json("infinity")},
      {"distortion", {{"k1", fit.distortion.k1}, {"k2", fit.distortion.k2}, {"k3", fit.distortion.k3}}},
      {"field_curvature_per_mm", fit.fieldCurvaturePerMm},
      {"chromatic",
       {{"lateral_red", fit.lateralRed},
        {"lateral_blue", fit.lateralBlue},
        {"inverse_focus_shift_red_per_mm", fit.inverseFocusShiftRedPerMm},
        {"inverse_focus_shift_blue_per_mm", fit.inverseFocusShiftBluePerMm}}},
      {"barrel", {{"distance_mm", fit.barrelDistanceMm}, {"diameter_mm", 2.0 * fit.barrelRadiusMm}}},
      {"vignetting", {{"a1", fit.illuminationGain.x}, {"a2", fit.illuminationGain.y}, {"a3", fit.illuminationGain.z}}},
      {"error",
       {{"position_um", e.positionUm},
        {"lateral_colour_um", e.lateralColourUm},
        {"focus_blur_um", e.focusBlurUm},
        {"illumination", e.illumination},
        {"aberration_blur_um", e.aberrationBlurUm},
        {"worst_um", e.worstUm()}}},
  };
}

void printFit(const FittedLens& fit, const std::function<void(const char*, const std::string&)>& line) {
  if (!fit.usable) {
    line("real-time fit", cat("none: ", fit.why));
    return;
  }
  const LensFitError& e = fit.error;
  line("real-time fit",
       cat("thin lens F ", fixed(fit.focalLengthMm, 3), " mm, pupil ", fixed(fit.entrancePupilDiameterMm, 3),
           " mm, focus ",
           fit.inverseFocusPerMm > 0.0 ? cat(fixed(1.0 / fit.inverseFocusPerMm, 1), " mm") : std::string("infinity"),
           " from the entrance pupil"));
  line("",
       cat("k1 ", fixed(fit.distortion.k1, 5), "  k2 ", fixed(fit.distortion.k2, 5), "  k3 ",
           fixed(fit.distortion.k3, 5), ", field curvature ", fixed(fit.fieldCurvaturePerMm * 1e3, 4), " /m per r^2"));
  line("", cat("barrel ",
               fit.barrelRadiusMm > 0.0 ? cat(fixed(2.0 * fit.barrelRadiusMm, 2), " mm across, ",
                                              fixed(fit.barrelDistanceMm, 2), " mm in front")
                                        : std::string("none"),
               ", vignetting a1 ", fixed(fit.illuminationGain.x, 4), " a2 ", fixed(fit.illuminationGain.y, 4), " a3 ",
               fixed(fit.illuminationGain.z, 4)));
  if (fit.lateralRed != 0.0 || fit.lateralBlue != 0.0)
    line("", cat("lateral colour R ", fixed(fit.lateralRed, 5), " B ", fixed(fit.lateralBlue, 5),
                 ", axial 1/z shift R ", fixed(fit.inverseFocusShiftRedPerMm * 1e3, 4), " B ",
                 fixed(fit.inverseFocusShiftBluePerMm * 1e3, 4), " /m"));
  line("fit error", cat("position ", fixed(e.positionUm, 2), " um, lateral colour ", fixed(e.lateralColourUm, 2),
                        " um, focus blur ", fixed(e.focusBlurUm, 2), " um, illumination ", fixed(e.illumination, 4)));
  line("", cat("aberration blur ", fixed(e.aberrationBlurUm, 2), " um RMS (no thin lens has it); worst ",
               fixed(e.worstUm(), 2), " um"));
}

nlohmann::json reportJson(const LensPrescription& lens, const LensReport& r, const LensAnalysisOptions& o) {
  const FirstOrder& f = r.firstOrder;
  nlohmann::json field = nlohmann::json::array();
  for (const FieldSample& s : r.field)
    field.push_back({{"field_fraction", s.fieldFraction},
                     {"image_height_mm", s.imageHeightMm},
                     {"field_angle_deg", s.fieldAngleDegrees},
                     {"distortion_percent", s.distortionPercent},
                     {"relative_illumination", s.relativeIllumination}});
  nlohmann::json j = {
      {"lens", lens.source},
      {"design", lens.comments.empty() ? "" : lens.comments.front()},
      {"sensor_mm", {o.sensorMm.x, o.sensorMm.y}},
      {"focus_distance_mm", o.focusDistanceMm > 0.0 && std::isfinite(o.focusDistanceMm)
                                ? nlohmann::json(o.focusDistanceMm)
                                : nlohmann::json("infinity")},
      {"focal_length_mm", f.focalLengthMm},
      {"back_focal_mm", f.backFocalMm},
      {"front_focal_mm", f.frontFocalMm},
      {"principal_planes_mm", {f.frontPrincipalMm, f.rearPrincipalMm}},
      {"length_mm", lens.lengthMm()},
      {"stop_diameter_mm", r.stopDiameterMm},
      {"f_number", f.fNumber},
      {"working_f_number", r.workingFNumber},
      {"magnification", r.magnification},
      {"entrance_pupil", {{"position_mm", f.entrancePupilMm}, {"diameter_mm", f.entrancePupilDiameterMm}}},
      {"exit_pupil", {{"position_mm", f.exitPupilMm}, {"diameter_mm", f.exitPupilDiameterMm}}},
      {"film_distance_mm", r.filmDistanceMm},
      {"field_of_view_deg",
       {{"horizontal", r.fieldOfViewDegrees.x},
        {"vertical", r.fieldOfViewDegrees.y},
        {"diagonal", r.fieldOfViewDegrees.z}}},
      {"field", field},
      {"distortion_fit",
       {{"k1", r.brownK.x}, {"k2", r.brownK.y}, {"k3", r.brownK.z}, {"rms_error_percent", r.brownRmsErrorPercent}}},
      {"rms_spot_mm", {r.rmsSpotMm.x, r.rmsSpotMm.y, r.rmsSpotMm.z}},
  };
  if (r.fisheye)
    j["equidistant_fit"] = {{"focal_length_mm", r.equidistantFocalMm},
                            {"rms_error_percent", r.equidistantRmsErrorPercent}};
  if (r.dispersion) j["colour"] = {{"axial_mm", r.axialColourMm}, {"lateral_mm", r.lateralColourMm}};
  return j;
}

void printReport(std::ostream& out, const LensPrescription& lens, const LensReport& r, const LensAnalysisOptions& o,
                 const FittedLens& fit) {
  const FirstOrder& f = r.firstOrder;
  const std::function<void(const char*, const std::string&)> line = [&](const char* name, const std::string& value) {
    out << name << std::string(22 - std::string(name).size(), ' ') << value << "\n";
  };
  const auto mm = [](double v) { return cat(fixed(v, 3), " mm"); };
  line("lens", lens.source);
  if (!lens.comments.empty()) line("design", lens.comments.front());
  line("surfaces",
       cat(lens.surfaces.size(), " (stop at row ", lens.stopIndex() + 1, "), length ", mm(lens.lengthMm())));
  line("focal length", mm(f.focalLengthMm));
  line("back focal distance", cat(mm(f.backFocalMm), " (last vertex to the rear focal point)"));
  line("front focal distance", mm(f.frontFocalMm));
  line("principal planes",
       cat("H ", mm(f.frontPrincipalMm), ", H' ", mm(f.rearPrincipalMm), " (from the first vertex)"));
  line("f-number", cat("f/", fixed(f.fNumber, 3), " paraxial (stop ", mm(r.stopDiameterMm), "), f/",
                       fixed(r.workingFNumber, 3), " working"));
  line("entrance pupil", cat(mm(f.entrancePupilDiameterMm), " across, at ", mm(f.entrancePupilMm)));
  line("exit pupil", cat(mm(f.exitPupilDiameterMm), " across, at ", mm(f.exitPupilMm)));
  const bool infinity = !(o.focusDistanceMm > 0.0) || std::isinf(o.focusDistanceMm);
  line("focus", infinity ? std::string("infinity")
                         : cat(mm(o.focusDistanceMm), " from the film, magnification ", fixed(r.magnification, 4)));
  line("film distance", cat(mm(r.filmDistanceMm), " behind the last vertex"));
  line("sensor", cat(fixed(o.sensorMm.x, 2), " x ", fixed(o.sensorMm.y, 2), " mm"));
  line("field of view", cat(fixed(r.fieldOfViewDegrees.x, 2), " x ", fixed(r.fieldOfViewDegrees.y, 2),
                            " deg, diagonal ", fixed(r.fieldOfViewDegrees.z, 2), " deg"));
  line("distortion fit", cat("k1 ", fixed(r.brownK.x, 5), "  k2 ", fixed(r.brownK.y, 5), "  k3 ", fixed(r.brownK.z, 5),
                             "  (rms ", fixed(r.brownRmsErrorPercent, 3), " % of the image height)"));
  if (r.fisheye)
    line("equidistant fit",
         cat("h = f theta, f ", mm(r.equidistantFocalMm), " (rms ", fixed(r.equidistantRmsErrorPercent, 3), " %)"));
  if (r.dispersion)
    line("colour", cat("axial ", mm(r.axialColourMm), " (F - C), lateral ", mm(r.lateralColourMm), " at the corner"));
  else
    line("colour", "no Abbe numbers in the file: one wavelength");
  line("rms spot", cat(fixed(1000.0 * r.rmsSpotMm.x, 2), " / ", fixed(1000.0 * r.rmsSpotMm.y, 2), " / ",
                       fixed(1000.0 * r.rmsSpotMm.z, 2), " um at 0 / 0.5 / 1.0 of the half diagonal"));
  printFit(fit, line);
  out << "\nfield   height_mm   angle_deg   distortion_%   relative_illumination\n";
  for (const FieldSample& s : r.field) {
    char row[128];
    std::snprintf(row, sizeof row, "%5.2f   %9.3f   %9.3f   %12.3f   %21.3f\n", s.fieldFraction, s.imageHeightMm,
                  s.fieldAngleDegrees, s.distortionPercent, s.relativeIllumination);
    out << row;
  }
}

int runLens(const LensCommandOptions& c) {
  if (!c.plot.empty()) {
    // Checked before any work, as every output is (io/OutputPath.h).
    if (fs::path(c.plot).extension() != ".svg")
      throw InputError(cat("--plot ", c.plot, ": the plot is drawn as SVG; give a file name ending in .svg"));
    checkOutputPath(c.plot, OutputKind::Any, "--plot");
    checkNotInput(c.plot, "--plot", c.file, "the lens file");
  }
  const LensPrescription lens = parseLensPrescription(readTextFile(c.file, "lens file"), c.file);
  LensAnalysisOptions o;
  o.sensorMm = parseSensorMm(c.sensor);
  if (c.focus != "infinity" && c.focus != "inf") {
    o.focusDistanceMm = readNumber("--focus-mm", c.focus, {.min = 1e-3, .max = 1e12, .unit = "millimetres"});
  }
  o.fNumber = c.fNumber;
  const LensReport report = analyseLens(lens, o);
  LensFitSettings fitSettings;
  fitSettings.sensorMm = o.sensorMm;
  fitSettings.fNumber = o.fNumber;
  fitSettings.focusDistanceMm = focusFromEntrancePupilMm(lens, report, o);
  const FittedLens fit = fitLens(lens, fitSettings);
  if (!c.plot.empty()) {
    OutputSet outputs;
    outputs.add(c.plot, lensPlotSvg(lens, report, o));
    outputs.commit();
  }
  if (c.json) {
    nlohmann::json j = reportJson(lens, report, o);
    j["fit"] = fitJson(fit);
    std::cout << j.dump(2) << "\n";
  } else {
    printReport(std::cout, lens, report, o, fit);
  }
  return 0;
}

}  // namespace

std::function<int()> addLensCommand(CLI::App& app) {
  auto o = std::make_shared<LensCommandOptions>();
  CLI::App* cmd =
      app.add_subcommand("lens",
                         "Describe a lens prescription: focal lengths, pupils, field of view, distortion and its "
                         "k1 k2 k3, relative illumination, colour, spot sizes (docs/lenses.md)");
  cmd->add_option("file", o->file,
                  "lens file: radius_mm thickness_mm index aperture_mm [abbe] per surface, scene side first "
                  "(assets/lenses/)")
      ->required();
  cmd->add_option("--sensor", o->sensor, "sensor size: WxH in mm (e.g. 36x24), or " + namedSensorList())
      ->type_name("WxH|NAME")
      ->capture_default_str();
  cmd->add_option("--focus-mm", o->focus, "focus distance from the film in mm, or infinity")
      ->type_name("MM")
      ->capture_default_str();
  cmd->add_option("--f-number", o->fNumber,
                  "close the stop to this paraxial f-number (default: the design's full opening)")
      ->check(numberIn({.min = 0.1, .max = 1e4, .unit = ""}))
      ->type_name("N");
  cmd->add_flag("--json", o->json, "print the report as JSON");
  cmd->add_option("--plot", o->plot,
                  "also draw the lens in section with rays from three field points, and its distortion and "
                  "relative illumination against field, into this SVG file")
      ->type_name("FILE.svg");
  return [cmd, o]() { return cmd->parsed() ? runLens(*o) : -1; };
}

}  // namespace lenslab
