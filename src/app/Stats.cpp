#include "app/Stats.h"

#include <nlohmann/json.hpp>

namespace lenslab {

std::string toJson(const RunStats& s) {
  nlohmann::json j;
  j["command"] = s.command;
  j["scene"] = s.scene;
  j["camera"] = s.camera;
  j["width"] = s.size.widthPx;
  j["height"] = s.size.heightPx;
  j["backend"] = s.backend;
  j["renderer"] = s.renderer;
  j["triangles"] = s.triangles;
  j["seconds"] = s.seconds;
  j["timings"] = {{"context_seconds", s.contextSeconds},
                  {"setup_seconds", s.setupSeconds},
                  {"render_seconds", s.renderSeconds},
                  {"write_seconds", s.writeSeconds}};
  nlohmann::json passes = nlohmann::json::array();
  for (const PlannedPass& p : s.plan.passes) passes.push_back({{"name", p.name}, {"why", p.why}, {"variants", p.variants}});
  j["plan"] = {{"passes", passes},
               {"aperture_samples", s.plan.apertureSamples},
               {"aperture_samples_why", s.plan.samplesWhy},
               {"pattern", patternName(s.plan.pattern)},
               {"seed", s.plan.seed},
               {"coc_px", {{"min", s.plan.cocMinPx}, {"max", s.plan.cocMaxPx}}},
               {"depth_range", {{"min", s.plan.depthMin}, {"max", s.plan.depthMax}}},
               {"views_per_sample", s.plan.viewsPerSample},
               {"render_size", {s.plan.overscan.size.widthPx, s.plan.overscan.size.heightPx}}};
  return j.dump(2) + "\n";
}

void writeStats(OutputSet& outputs, const std::filesystem::path& path, const RunStats& stats) {
  outputs.add(path, toJson(stats));
}

}  // namespace lenslab
