#include "report/Sweep.h"

#include "camera/ImageMap.h"
#include "camera/Projection.h"
#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/GatherDof.h"
#include "render/Renderer.h"
#include "render/VisibleBlurPass.h"
#include "plan/TileBudget.h"
#include "report/Plot.h"


#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

// The adaptive series' aperture pattern: its rows' pattern and its images' names.
constexpr const char* kAdaptivePattern = "sobol";

// FNV-1a, 64 bits: a cache key, not a security measure.
struct Hash {
  std::uint64_t value = 1469598103934665603ull;
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) value = (value ^ p[i]) * 1099511628211ull;
  }
  template <class T>
  void addVector(const std::vector<T>& v) { add(v.data(), v.size() * sizeof(T)); }
  void addString(const std::string& s) { add(s.data(), s.size()); }
};

// A texture reference, field by field (glm's matrices hold their floats without padding).
void addTextureRef(Hash& h, const TextureRef& t) {
  const int ints[] = {t.texture, t.texCoord};
  h.add(ints, sizeof ints);
  h.add(&t.uvFromTexCoord, sizeof t.uvFromTexCoord);
}

// What a material adds to the base colour: emission, metallic-roughness, occlusion, normal map.
void addShadingFields(Hash& h, const Material& m) {
  h.add(&m.emissive, sizeof m.emissive);
  h.add(&m.emissiveTexture, sizeof m.emissiveTexture);
  const float factors[] = {m.metallicFactor, m.roughnessFactor, m.occlusionStrength, m.normalScale};
  h.add(factors, sizeof factors);
  for (const TextureRef* t : {&m.metallicRoughnessTexture, &m.occlusionTexture, &m.normalTexture}) addTextureRef(h, *t);
}

void addLight(Hash& h, const PunctualLight& l) {
  const int type = static_cast<int>(l.type);
  h.add(&type, sizeof type);
  const float floats[] = {l.color.r, l.color.g, l.color.b, l.intensity, l.innerConeAngleRadians, l.outerConeAngleRadians};
  h.add(floats, sizeof floats);
  const double doubles[] = {l.range, l.worldPosition.x, l.worldPosition.y, l.worldPosition.z,
                            l.worldDirection.x, l.worldDirection.y, l.worldDirection.z};
  h.add(doubles, sizeof doubles);
}

// The environment both renderers light with and show: every map's pixels (the source image is
// the background, so its contents; the prefiltered levels, so the prefilter settings too), the
// intensity and the rotation. The pixels, not the file's name or bytes: the scene holds the maps,
// and the same pixels light alike whatever file they came from. (studio.hdr's maps, 8.3 MB, take
// 60–80 ms of byte-wise FNV-1a on the shared 2-core machine, once a sweep: small beside the
// reference, which takes seconds to minutes.)
void addEnvironment(Hash& h, const EnvironmentLookup* environment) {
  const int present = environment != nullptr;
  h.add(&present, sizeof present);
  if (!environment) return;
  const auto addImage = [&h](const EnvironmentImage& image) {
    const int size[] = {image.width, image.height};
    h.add(size, sizeof size);
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "texels are hashed as their bytes: no padding");
    h.addVector(image.rgb);
  };
  const PrefilteredEnvironment& maps = environment->maps();
  addImage(maps.background);
  addImage(maps.diffuse);
  const int levels = maps.specularLevels();
  h.add(&levels, sizeof levels);
  for (const EnvironmentImage& level : maps.specular) addImage(level);
  const EnvironmentPlacement& placement = environment->placement();
  h.add(&placement.rotationDegrees, sizeof placement.rotationDegrees);
  h.add(&placement.intensity, sizeof placement.intensity);
}

}  // namespace

std::string referenceKey(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& o) {
  Hash h;
  // v2: textures filtered per sample (the pixel integral, not a pixel-blurred image), two halves.
  h.addString("lenslab reference v2");
  // v3: glTF metallic-roughness shading and punctual lights (shaders/common/brdf.glsl).
  h.addString("v3 metallic-roughness");
  // v4: the environment (--environment): its maps, intensity and rotation.
  h.addString("v4 environment");
  for (const Mesh& m : scene.meshes) {
    h.addVector(m.vertices);
    h.addVector(m.indices);
    h.add(&m.material, sizeof m.material);
  }
  // Field by field: a struct's padding bytes are unspecified, so hashing whole structs could give
  // another key for the same scene on another run.
  static_assert(sizeof(Vertex) == 18 * sizeof(float), "Vertex is hashed as its bytes: it must have no padding");
  for (const Instance& i : scene.instances) {
    h.add(&i.mesh, sizeof i.mesh);
    h.add(&i.worldFromModel, sizeof i.worldFromModel);
  }
  for (const Material& m : scene.materials) {
    h.add(&m.baseColorFactor, sizeof m.baseColorFactor);
    const int flags[] = {m.baseColorTexture.texture, m.unlit, static_cast<int>(m.alphaMode), m.doubleSided};
    h.add(flags, sizeof flags);
    h.add(&m.alphaCutoff, sizeof m.alphaCutoff);
    addShadingFields(h, m);
    // Texture references: which uv set and transform (normal maps and KHR_texture_transform).
    for (const TextureRef* r : {&m.baseColorTexture, &m.emissiveTexture, &m.normalTexture}) {
      const int ref[] = {r->texture, r->texCoord};
      h.add(ref, sizeof ref);
      h.add(&r->uvFromTexCoord, sizeof r->uvFromTexCoord);
    }
    h.add(&m.normalScale, sizeof m.normalScale);
  }
  for (const PunctualLight& light : scene.lights) addLight(h, light);
  for (const TextureImage& i : scene.images) h.addVector(i.rgba8);
  for (const Texture& t : scene.textures) {
    const int fields[] = {t.image, static_cast<int>(t.sampler.wrapS), static_cast<int>(t.sampler.wrapT),
                          static_cast<int>(t.sampler.magFilter), static_cast<int>(t.sampler.minFilter)};
    h.add(fields, sizeof fields);
  }
  addEnvironment(h, scene.environment.get());
  // The real lens (sweep --lens) when the reference traces one; nothing otherwise, so that the
  // thin lens's keys stay as they were.
  if (!o.lensKey.empty()) h.addString("lens " + o.lensKey);
  const Lighting& l = scene.lighting;
  const float lighting[] = {l.toLight.x, l.toLight.y, l.toLight.z, l.ambient, l.diffuse, l.background.r, l.background.g, l.background.b};
  h.add(lighting, sizeof lighting);
  h.addString(toCameraJson(camera));
  h.add(&camera.apertureRadius, sizeof camera.apertureRadius);
  const double inverseFocus = camera.inverseFocusDistance();
  h.add(&inverseFocus, sizeof inverseFocus);
  const long long ints[] = {size.widthPx, size.heightPx, o.referenceSpp, o.seed};
  h.add(ints, sizeof ints);
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << h.value;
  return s.str();
}

namespace {

std::vector<int> doublings(int max) {
  std::vector<int> n;
  for (int k = 1; k <= max; k *= 2) n.push_back(k);
  return n;
}

void say(const SweepOptions& o, const std::string& line) {
  if (o.log) o.log(line);
}

}  // namespace

std::vector<bool> occlusionEdgeMask(const Camera& camera, ImageSize size, const std::vector<double>& depth) {
  const int w = size.widthPx, h = size.heightPx;
  const double pxPerUnit = w / camera.view.window.width();
  std::vector<bool> mask(depth.size(), false);
  auto depthAt = [&](int x, int y) { return depth[static_cast<std::size_t>(y * w + x)]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = depthAt(x, y);
      const double coc = std::isfinite(d) ? cocDiameterOnWindow(camera, d) : cocDiameterOnWindow(camera, 1e30);
      const int r = static_cast<int>(std::ceil(std::clamp(0.5 * coc * pxPerUnit, 1.0, 32.0)));
      bool edge = false;
      for (int dy = -r; dy <= r && !edge; ++dy)
        for (int dx = -r; dx <= r && !edge; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= w || qy >= h || dx * dx + dy * dy > r * r) continue;
          const double e = depthAt(qx, qy);
          if (std::isinf(d) != std::isinf(e)) edge = true;
          else if (std::isfinite(d) && std::abs(d - e) > 0.05 * std::min(d, e)) edge = true;
        }
      mask[static_cast<std::size_t>(y * w + x)] = edge;
    }
  return mask;
}

double maskedRmse(const Image& a, const Image& b, const std::vector<bool>& mask) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) {
      for (int k = 0; k < 3; ++k) {
        const double d = static_cast<double>(a.rgba[i * 4 + static_cast<std::size_t>(k)]) - b.rgba[i * 4 + static_cast<std::size_t>(k)];
        sum += d * d;
      }
      n += 3;
    }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

SweepResult runSweep(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& o) {
  if (camera.isPinhole())
    throw InputError("sweep: the camera is a pinhole, so there is no depth of field to converge to; give a camera with "
                     "f_number (physical form) or aperture_radius (lecture form), or --f-number N");
  SweepResult result;
  const fs::path imageDir = o.outDir.empty() ? fs::path() : o.outDir / "images";
  assert(o.outDir.empty() || o.outputs);
  if (!imageDir.empty()) o.outputs->createFolders(imageDir);

  // The reference, cached: two independent halves of the samples (other seeds), averaged. Their
  // difference measures the reference's own noise, which bounds every PSNR the sweep can show:
  // the halves' difference has twice a half's variance, and their mean half of it, so the
  // reference's RMSE against its own limit is RMSE(a, b) / 2.
  const RayCaster caster(scene);
  Image halves[2];
  const std::string key = referenceKey(scene, camera, size, o);
  for (int k = 0; k < 2; ++k) {
    const fs::path cached = o.outDir.empty() ? fs::path() : o.outDir / cat("reference-", key, k == 0 ? "-a" : "-b", ".exr");
    if (!cached.empty() && fs::exists(cached)) {
      halves[k] = readImage(cached);
      if (halves[k].width == size.widthPx && halves[k].height == size.heightPx) {
        result.referenceCached = true;
        continue;
      }
    }
    result.referenceCached = false;
    say(o, cat("reference: ray casting ", size.widthPx, "x", size.heightPx, " at ", o.referenceSpp / 2, " spp (half ", k + 1,
               " of 2", cached.empty() ? std::string() : cat(", cached as ", cached.filename().string()), ")"));
    const auto t = std::chrono::steady_clock::now();
    const RaycastOptions half{std::max(1, o.referenceSpp / 2), o.seed ^ (k == 0 ? 0x9e3779b9u : 0x7f4a7c15u)};
    const auto rowsDone = [&](int rows, int height) {
      if (o.progress) o.progress("reference rows", std::int64_t{k} * height + rows, 2 * std::int64_t{height});
    };
    halves[k] = o.exactLens ? caster.render(*o.exactLens, camera, size, half, rowsDone) : caster.render(camera, size, half, rowsDone);
    result.referenceSeconds += secondsSince(t);
    if (!cached.empty()) writeImage(*o.outputs, cached, halves[k]);
  }
  Image reference(size.widthPx, size.heightPx);
  for (std::size_t i = 0; i < reference.rgba.size(); ++i) reference.rgba[i] = 0.5f * (halves[0].rgba[i] + halves[1].rgba[i]);
  result.referenceNoiseRmse = 0.5 * compareImages(halves[0], halves[1], 0.0).rmse;

  const auto setupStart = std::chrono::steady_clock::now();
  Renderer renderer(scene);
  GatherDof gather;
  // Occlusion edges from the pinhole depth; and a warm-up frame (first-frame shader JIT).
  // With distortion the depth is looked up where each pixel's true perspective position is, in
  // the overscanned pinhole view (nearest pixel: the mask only needs to find the edges).
  const ThinLensMap map = ThinLensMap(camera, size).overscanned();
  const Overscan& overscan = map.overscan();
  std::vector<float> zNdc = renderer.pinholeDepth(overscan.camera, overscan.size);
  std::vector<double> depth(static_cast<std::size_t>(size.widthPx) * static_cast<std::size_t>(size.heightPx));
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec2 centre(x + 0.5, y + 0.5);
      const glm::dvec2 p = map.renderPixelFromOutput(centre);
      const int px = std::clamp(static_cast<int>(p.x), 0, overscan.size.widthPx - 1);
      const int py = std::clamp(static_cast<int>(p.y), 0, overscan.size.heightPx - 1);
      depth[static_cast<std::size_t>(y * size.widthPx + x)] =
          depthFromReverseZ(camera.view, zNdc[static_cast<std::size_t>(py * overscan.size.widthPx + px)]);
    }
  const std::vector<bool> edges = occlusionEdgeMask(camera, size, depth);
  result.edgeFraction = static_cast<double>(std::count(edges.begin(), edges.end(), true)) / static_cast<double>(edges.size());
  renderer.render(camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 2, 2, o.seed}), size);
  (void)gather.apply(camera, renderer.renderPinhole(camera, size), 8);
  result.setupSeconds = secondsSince(setupStart);

  // Raster and post-process frames are short and the machine is noisy: each is timed three times
  // and the median kept (the image is the same every time: fixed seeds).
  auto medianOf3 = [](const std::function<Image()>& frame, Image& image) {
    double t[3];
    for (double& ti : t) {
      const auto start = std::chrono::steady_clock::now();
      image = frame();
      ti = secondsSince(start);
    }
    std::sort(std::begin(t), std::end(t));
    return t[1];
  };

  const auto wanted = [&](const std::string& series) {
    return std::find(o.series.begin(), o.series.end(), series) != o.series.end();
  };
  // Each series' budgets, an image each: views (lecture17 its own 17), spp or taps; none when it does
  // not run. The adaptive series runs to its targets instead (counted apart).
  const auto budgetsOf = [&](const std::string& series) -> std::vector<int> {
    if (!wanted(series) || series == "adaptive") return {};
    if (series == "lecture17") return {17};
    if (series == "raycast") return doublings(o.maxSpp);
    // The gather baseline blurs the pinhole image with round disks and knows no lens effects:
    // comparing it with an exact distorted (or polygonal) reference would measure what it lacks,
    // not the method.
    if (series == "postprocess") return camera.effects.isZero() && camera.aperture.isRound() ? o.gatherTaps : std::vector<int>{};
    return doublings(o.maxViews);
  };
  std::int64_t imagesPlanned = wanted("adaptive") ? static_cast<std::int64_t>(o.targetsDb.size()) : 0;
  for (const std::string& series : sweepSeriesNames()) imagesPlanned += static_cast<std::int64_t>(budgetsOf(series).size());
  imagesPlanned += static_cast<std::int64_t>(o.lensAblations.size());
  std::set<std::string> imageNames;
  // `target`: the adaptive row's target PSNR (its image's name), 0 for the others.
  auto record = [&](const std::string& method, const std::string& pattern, int samples, double seconds, const Image& image,
                    double target = 0.0) {
    const ImageDifference d = compareImages(image, reference, 0.0);
    SweepRow row;
    row.method = method;
    row.pattern = pattern;
    row.samples = samples;
    row.seconds = seconds;
    row.rmse = d.rmse;
    row.psnr = d.psnrDb;
    row.maxError = d.maxAbs;
    row.edgeRmse = maskedRmse(image, reference, edges);
    row.targetPsnr = target;
    if (!imageDir.empty()) {
      row.image = sweepImageName(row);
      // Two rows with one name would leave fewer files than rows (and the report would lie). Cannot
      // happen from the command line, which refuses targets that share a name before any work.
      if (!imageNames.insert(row.image).second) throw std::logic_error(cat("sweep: two rows named ", row.image));
      writeImage(*o.outputs, imageDir / row.image, image);
    }
    result.rows.push_back(row);
    if (o.progress) o.progress("images", static_cast<std::int64_t>(result.rows.size()), imagesPlanned);
  };
  for (AperturePattern pattern : {AperturePattern::Lecture17, AperturePattern::Concentric, AperturePattern::R2, AperturePattern::Random,
                                  AperturePattern::Sobol}) {
    if (!wanted(patternName(pattern))) continue;
    for (int n : budgetsOf(patternName(pattern))) {
      const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{pattern, n, n, o.seed});
      Image image;
      const double seconds = medianOf3([&] { return renderer.render(camera, plan, size); }, image);
      record("raster", patternName(pattern), n, seconds, image);
    }
    say(o, cat("raster ", patternName(pattern), ": done"));
  }
  if (wanted("adaptive")) {
    // The whole of an adaptive frame is timed: the pre-pass, the plan from it, and the rounds.
    for (const double target : o.targetsDb) {
      PlanOptions options{AperturePattern::Sobol, 0, o.maxViews, o.seed};
      options.targetPsnrDb = target;
      FrameEstimate estimate;
      Image image;
      const double seconds = medianOf3([&] {
        const VisibleBlur visible = measureVisibleBlur(renderer, camera, size);
        const FramePlan plan = makeFramePlan(scene, camera, size, options, &visible);
        Image frame = renderer.render(camera, plan, size);
        estimate = renderer.estimate();
        return frame;
      }, image);
      record("adaptive", kAdaptivePattern, static_cast<int>(std::lround(estimate.meanSamples)), seconds, image, target);
      SweepRow& row = result.rows.back();
      row.estimatePsnr = estimate.psnrDb;
      row.maxTileSamples = estimate.maxSamples;
      row.meanSamples = estimate.meanSamples;
    }
    say(o, "adaptive: done");
  }
  for (const auto& [effect, without] : o.lensAblations) {
    const FramePlan plan = makeFramePlan(scene, without, size, PlanOptions{AperturePattern::Sobol, o.maxViews, o.maxViews, o.seed});
    Image image;
    const double seconds = medianOf3([&] { return renderer.render(without, plan, size); }, image);
    record("fitted-without", effect, o.maxViews, seconds, image);
  }
  if (!o.lensAblations.empty()) say(o, "fitted lens, each effect left out: done");
  for (int spp : budgetsOf("raycast")) {
    const auto t = std::chrono::steady_clock::now();
    const Image image = o.exactLens ? caster.render(*o.exactLens, camera, size, RaycastOptions{spp, o.seed})
                                    : caster.render(camera, size, RaycastOptions{spp, o.seed});
    record("raycast", "stratified", spp, secondsSince(t), image);
  }
  if (wanted("raycast")) say(o, "raycast: done");
  const std::vector<int> gatherTaps = budgetsOf("postprocess");
  if (gatherTaps.empty() && !o.gatherTaps.empty() && wanted("postprocess")) say(o, camera.effects.isZero() ? "postprocess gather: left out (it blurs with round disks only)"
                                                                                                   : "postprocess gather: left out (it has no lens effects)");
  for (int taps : gatherTaps) {
    Image image;
    const double seconds = medianOf3([&] { return gather.apply(camera, renderer.renderPinhole(camera, size), taps); }, image);
    record("postprocess", "gather", taps, seconds, image);
  }
  say(o, "postprocess: done");
  return result;
}

std::string sweepImageName(const SweepRow& row) {
  if (row.method == "adaptive") return cat(row.method, "-", row.pattern, "-", row.targetPsnr, "dB.png");
  return cat(row.method, "-", row.pattern, "-", row.samples, ".png");
}

std::string sweepAdaptiveImageName(double targetPsnrDb) {
  SweepRow row;
  row.method = "adaptive";
  row.pattern = kAdaptivePattern;
  row.targetPsnr = targetPsnrDb;
  return sweepImageName(row);
}

std::vector<std::string> sweepSeriesNames() {
  return {"lecture17", "concentric", "r2", "random", "sobol", "adaptive", "raycast", "postprocess"};
}

double secondsToReach(const std::vector<const SweepRow*>& rows, double psnrDb) {
  // In the order run (rising budgets): the first row at or above the target, and the one before.
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i]->psnr < psnrDb) continue;
    if (i == 0 || rows[i - 1]->psnr >= rows[i]->psnr || rows[i - 1]->seconds <= 0.0) return rows[i]->seconds;
    const SweepRow& a = *rows[i - 1];
    const SweepRow& b = *rows[i];
    const double f = (psnrDb - a.psnr) / (b.psnr - a.psnr);
    return std::exp(std::log(a.seconds) + f * (std::log(b.seconds) - std::log(a.seconds)));
  }
  return -1.0;
}

std::string sweepCsv(const SweepResult& r) {
  std::ostringstream s;
  s.precision(8);
  s << "method,pattern,samples,seconds,rmse,psnr,max_error,edge_rmse,target_psnr,estimate_psnr,mean_samples,max_tile_samples\n";
  for (const SweepRow& row : r.rows)
    s << row.method << "," << row.pattern << "," << row.samples << "," << row.seconds << "," << row.rmse << ","
      << row.psnr << "," << row.maxError << "," << row.edgeRmse << "," << row.targetPsnr << "," << row.estimatePsnr << ","
      << row.meanSamples << "," << row.maxTileSamples << "\n";
  return s.str();
}

std::string sweepMarkdown(const SweepResult& r, const std::string& header) {
  std::map<std::string, std::vector<const SweepRow*>> series;
  std::vector<std::string> order;
  for (const SweepRow& row : r.rows) {
    const std::string key = row.method + " " + row.pattern;
    if (!series.count(key)) order.push_back(key);
    series[key].push_back(&row);
  }
  const std::array<double, 4> levels = {30.0, 35.0, 40.0, 45.0};
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s << header << "\n";
  s << "## Time to reach a PSNR\n\nSeconds, interpolated between the series' last row below the PSNR and its first row "
       "at or above it (PSNR linear in log time); — where no row reaches it. PSNR against the reference.\n\n";
  s << "| method | 30 dB | 35 dB | 40 dB | 45 dB | best PSNR | edge RMSE at best | slope d log RMSE / d log N |\n|---|---|---|---|---|---|---|---|\n";
  for (const std::string& key : order) {
    const auto& rows = series[key];
    s << "| " << key << " |";
    for (const double target : levels) {
      const double t = secondsToReach(rows, target);
      if (t < 0.0) s << " — |";
      else s << " " << std::setprecision(4) << t << " |";
    }
    const SweepRow* top = rows.front();
    for (const SweepRow* row : rows)
      if (row->psnr > top->psnr) top = row;
    s << " " << std::setprecision(1) << top->psnr << " dB (" << top->samples << ") | " << std::setprecision(4) << top->edgeRmse << " |";
    // Least-squares slope of log RMSE against log samples (N = 1 included).
    if (rows.size() >= 3 && rows.front()->method != "adaptive") {
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (const SweepRow* row : rows) {
        const double x = std::log(static_cast<double>(row->samples)), y = std::log(row->rmse);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
      }
      const double n = static_cast<double>(rows.size());
      s << " " << std::setprecision(2) << (n * sxy - sx * sy) / (n * sxx - sx * sx) << " |\n";
    } else {
      s << " — |\n";
    }
  }
  // The equal-error table: at each PSNR, the fastest uniform pattern (named), the default pattern,
  // the per-tile method and the ray caster, and the per-tile method's speed-up over the fastest
  // uniform pattern — "faster" is against the best alternative, not the default.
  const std::string defaultKey = std::string("raster ") + patternName(PlanOptions{}.pattern);
  std::string adaptiveKey;
  for (const std::string& key : order)
    if (key.rfind("adaptive ", 0) == 0) adaptiveKey = key;
  const auto timeOf = [&](const std::string& key, double target) { return series.count(key) ? secondsToReach(series[key], target) : -1.0; };
  const auto cell = [&](double seconds) {
    std::ostringstream c;
    c.setf(std::ios::fixed);
    if (seconds < 0.0) c << "—";
    else c << std::setprecision(4) << seconds;
    return c.str();
  };
  bool anyRaster = false;
  for (const std::string& key : order) anyRaster |= key.rfind("raster ", 0) == 0;
  if (anyRaster && (!adaptiveKey.empty() || series.count("raycast stratified"))) {
    s << "\n## Equal error: seconds to each PSNR, side by side\n\nThe fastest uniform raster pattern at each PSNR (named), "
         "the default pattern (`" << defaultKey.substr(7) << "`), per-tile budgets and the ray caster, each interpolated as above; "
         "the speed-up is the fastest uniform pattern's time over the per-tile budgets' time.\n\n"
         "| PSNR | fastest uniform (s) | default `" << defaultKey.substr(7) << "` (s) | per-tile budgets (s) | ray cast (s) | per-tile speed-up |\n"
         "|---|---|---|---|---|---|\n";
    for (const double target : levels) {
      std::string bestKey;
      double best = -1.0;
      for (const std::string& key : order) {
        if (key.rfind("raster ", 0) != 0) continue;
        const double t = timeOf(key, target);
        if (t >= 0.0 && (best < 0.0 || t < best)) best = t, bestKey = key;
      }
      const double adaptive = adaptiveKey.empty() ? -1.0 : timeOf(adaptiveKey, target);
      s << "| " << std::setprecision(0) << target << " dB | " << cell(best);
      if (best >= 0.0) s << " (" << bestKey.substr(7) << ")";
      s << " | " << cell(timeOf(defaultKey, target)) << " | " << cell(adaptive) << " | " << cell(timeOf("raycast stratified", target)) << " | ";
      if (best < 0.0 || adaptive < 0.0) s << "— |\n";
      else s << std::setprecision(2) << best / adaptive << "x |\n";
    }
  }
  if (series.count("adaptive sobol")) {
    const double referenceMse = r.referenceNoiseRmse * r.referenceNoiseRmse;
    s << "\n## The estimate against the truth\n\nEach adaptive frame's own estimate (against its converged limit, from "
         "its two sample streams) beside its PSNR against the reference, and against the reference less the "
         "reference's own noise (its MSE, from its two halves, subtracted).\n\n"
         "| target | estimate | PSNR vs reference | less the reference's noise | estimate − truth | samples per pixel (busiest tile) |\n"
         "|---|---|---|---|---|---|\n";
    for (const SweepRow* row : series["adaptive sobol"]) {
      const double corrected = psnrFromMse(std::max(row->rmse * row->rmse - referenceMse, 1e-30));
      s << "| " << std::setprecision(1) << row->targetPsnr << " dB | " << std::setprecision(2) << row->estimatePsnr << " dB | "
        << row->psnr << " dB | " << corrected << " dB | " << std::showpos << row->estimatePsnr - corrected << std::noshowpos
        << " dB | " << std::setprecision(1) << row->meanSamples << " (" << row->maxTileSamples << ") |\n";
    }
  }
  if (!series.empty()) {
    // sweep --lens: the fit with everything against the fit with each effect left out, at the
    // largest raster budget, both against the exact lens.
    const SweepRow* full = nullptr;
    std::vector<const SweepRow*> without;
    for (const SweepRow& row : r.rows) {
      if (row.method == "fitted-without") without.push_back(&row);
    }
    for (const SweepRow& row : r.rows)
      if (!without.empty() && row.method == "raster" && row.pattern == "sobol" && row.samples == without.front()->samples) full = &row;
    if (full) {
      s << "\n## The fitted lens, effect by effect\n\nThe real-time camera fitted to the lens, against the lens traced exactly, "
           "with all its effects and with each left out in turn (" << full->samples << " views, sobol): the drop is what the fitted "
           "effect buys.\n\n| fitted camera | PSNR (dB) | RMSE | drop (dB) |\n|---|---|---|---|\n";
      s << "| all effects | " << std::setprecision(2) << full->psnr << " | " << std::setprecision(5) << full->rmse << " | — |\n";
      for (const SweepRow* row : without)
        s << "| without " << row->pattern << " | " << std::setprecision(2) << row->psnr << " | " << std::setprecision(5) << row->rmse
          << " | " << std::setprecision(2) << full->psnr - row->psnr << " |\n";
    }
  }
  s << "\n## All rows\n\n| method | pattern | samples | seconds | RMSE | PSNR (dB) | max error | edge RMSE |\n|---|---|---|---|---|---|---|---|\n";
  for (const SweepRow& row : r.rows)
    s << "| " << row.method << " | " << row.pattern << " | " << row.samples << " | " << std::setprecision(4) << row.seconds
      << " | " << std::setprecision(5) << row.rmse << " | " << std::setprecision(2) << row.psnr << " | " << std::setprecision(4)
      << row.maxError << " | " << std::setprecision(5) << row.edgeRmse << " |\n";
  return s.str();
}

}  // namespace lenslab
