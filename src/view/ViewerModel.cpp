// lenslab view: the rules behind the window (ViewerModel.h). Nothing here draws or reads input.
#include "view/ViewerModel.h"

#include "camera/DepthRange.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "camera/ViewSpec.h"
#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace lenslab::view {

// ---- the sample budget ----

int SampleBudget::samplesForFrame(int remaining) const {
  if (remaining <= 0) return 0;
  if (!(msPerSample_ > 0.0)) return 1;  // nothing measured yet: one sample tells the cost
  // The division can exceed an int's range when a sample costs next to nothing.
  const double affordable = std::min(frameBudgetMs_ / msPerSample_, static_cast<double>(remaining));
  return std::clamp(static_cast<int>(affordable), 1, remaining);
}

void SampleBudget::measured(int added, double ms, bool complete) {
  msPerSample_ = ms / std::max(added, 1);
  accumulationMs_ += ms;
  if (complete) convergedAfterMs_ = std::chrono::duration<double, std::milli>(Clock::now() - restartTime_).count();
}

void SampleBudget::restart() {
  accumulationMs_ = 0.0;
  convergedAfterMs_ = -1.0;
  restartTime_ = Clock::now();
}

// ---- the outside view's orbit ----

void OutsideOrbit::orbit(double azimuthStep, double elevationStep) {
  azimuthRadians += azimuthStep;
  elevationRadians = std::clamp(elevationRadians + elevationStep, -1.5, 1.5);
}

void OutsideOrbit::zoomBy(double wheelSteps) { zoom = std::clamp(zoom * std::pow(0.9, wheelSteps), 0.05, 50.0); }

Camera OutsideOrbit::cameraFor(const Camera& c, double aspect) const {
  const glm::dvec3 prp = prpWorld(c.view);
  const glm::dvec3 focus = focusPivotWorld(c);
  const glm::dvec3 pivot = 0.5 * (prp + focus);
  const double extent = std::max({c.view.prp.z, c.view.window.width(), c.view.window.height()});
  const double distance = 2.2 * extent * zoom;
  // Azimuth from behind the camera (its +n, flattened onto the ground) toward its right.
  const ViewBasis b = viewBasis(c.view);
  glm::dvec3 back(b.n.x, 0.0, b.n.z);
  back = glm::length(back) > 1e-6 ? glm::normalize(back) : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 right = glm::cross(glm::dvec3(0.0, 1.0, 0.0), back);
  const glm::dvec3 dir =
      std::cos(elevationRadians) * (std::cos(azimuthRadians) * back + std::sin(azimuthRadians) * right) +
      std::sin(elevationRadians) * glm::dvec3(0.0, 1.0, 0.0);
  PhysicalCamera p;
  p.eye = pivot + distance * dir;
  p.target = pivot;
  p.up = std::abs(dir.y) > 0.99 ? -back : glm::dvec3(0.0, 1.0, 0.0);
  p.focalLengthMm = 20.0;
  p.sensorMm = {24.0 * aspect, 24.0};
  // A pinhole: infinity focus puts no bound on how close it may come (no focus inside f).
  p.focusDistance = std::numeric_limits<double>::infinity();
  p.nearDistance = 1e-3 * distance;
  return toCamera(p, "outside view");
}

// ---- the model ----

ViewerModel::ViewerModel(const Scene& scene, EditableCamera camera, ImageSize size, PlanOptions planOptions,
                         double frameBudgetMs, std::ostream& errorLog)
    : scene_(scene),
      errorLog_(errorLog),
      size_(size),
      planOptions_(planOptions),
      cam_(std::move(camera)),
      lastGood_(cam_),
      baseSource_(cam_.camera.source),
      budget_(frameBudgetMs) {}

void ViewerModel::reportError(const std::string& message) {
  error_ = message;
  errorLog_ << "lenslab: error: " << message << "\n";
}

void ViewerModel::orbit(double yawRadians, double pitchRadians) {
  cam_ = orbited(cam_, yawRadians, pitchRadians);
  dirty_ = true;
}

void ViewerModel::lookAround(double yawRadians, double pitchRadians) {
  cam_ = lookedAround(cam_, yawRadians, pitchRadians);
  dirty_ = true;
}

void ViewerModel::fly(glm::dvec3 direction, double seconds, bool fast) {
  const double speed = 0.5 * cam_.camera.view.prp.z * (fast ? 4.0 : 1.0);
  cam_ = flown(cam_, direction * speed * seconds);
  dirty_ = true;
}

void ViewerModel::moveForward(double wheelSteps) {
  cam_ = flown(cam_, {0.0, 0.0, 0.1 * wheelSteps * cam_.camera.view.prp.z});
  dirty_ = true;
}

void ViewerModel::editLecture(const Camera& camera) {
  cam_.camera = camera;
  cam_.physical.reset();
  dirty_ = true;
}

void ViewerModel::refocus(double distance) {
  try {
    const SelectedCamera r = refocused(SelectedCamera{cam_.camera, cam_.physical}, distance, "focus distance");
    cam_.camera = r.camera;
    cam_.physical = r.physical;
    dirty_ = true;
  } catch (const InputError& e) {
    reportError(e.what());
  }
}

void ViewerModel::editPhysical(const PhysicalCamera& physical) {
  try {
    const Camera before = cam_.camera;
    cam_ = fromPhysical(physical, before.source, before.lens);
    cam_.camera.calibratedSize = before.calibratedSize;
    dirty_ = true;
  } catch (const InputError& e) {
    reportError(e.what());
  }
}

bool ViewerModel::canDescribeAsLens() const {
  const ViewSpec& s = cam_.camera.view;
  return s.projection == Projection::Perspective &&
         glm::length(glm::dvec2(s.prp.x, s.prp.y) - s.window.center()) < 1e-9 * std::max(1.0, s.prp.z);
}

void ViewerModel::describeAsLens() {
  try {
    const ViewSpec& s = cam_.camera.view;
    const glm::dvec2 sensor(36.0, 36.0 * s.window.height() / s.window.width());
    PhysicalCamera p = toPhysical(cam_.camera, sensor);
    if (cam_.camera.lens.apertureRadius > 0.0)
      p.fNumber = p.focalLengthMm * kMetresPerMillimetre / (2.0 * cam_.camera.lens.apertureRadius);
    editPhysical(p);
  } catch (const InputError& e) {
    reportError(e.what());
  }
}

void ViewerModel::editLensEffects(const LensEffects& effects) {
  Camera c = cam_.camera;
  c.lens.effects = effects;
  try {
    validateLensEffects(c, "the panel's lens");
    cam_.camera = c;
    dirty_ = true;
  } catch (const InputError& e) {
    reportError(e.what());
  }
}

void ViewerModel::setPlanOptions(const PlanOptions& options) {
  planOptions_ = options;
  dirty_ = true;
}

double ViewerModel::focusAt(glm::dvec2 pixel, const DepthAtPixel& depthAt, const std::string& asked) {
  // The camera's source names only the latest click, not every click since the start.
  Camera current = cam_.camera;
  current.source = baseSource_;
  const SelectedCamera focused = focusOnPixel(SelectedCamera{current, cam_.physical}, size_, pixel, depthAt, asked);
  const double distance = focused.camera.focusDistance();
  cam_.camera = focused.camera;
  cam_.physical = focused.physical;
  focusDistance_ = distance;
  dirty_ = true;
  return distance;
}

std::optional<double> ViewerModel::clickAt(glm::dvec2 pixel, const DepthAtPixel& depthAt) {
  try {
    return focusAt(pixel, depthAt, "click at image pixel");
  } catch (const InputError& e) {
    reportError(e.what());
    return std::nullopt;
  }
}

void ViewerModel::replanWith(const VisibleBlur& visible) {
  plan_ = makeFramePlan(scene_, cam_.camera, size_, planOptions_, &visible);
}

bool ViewerModel::wantsVisibleBlur() const {
  return !cam_.camera.lens.isPinhole() && (planOptions_.apertureSamples == 0 || planOptions_.targetPsnrDb.has_value());
}

Camera ViewerModel::renderCamera() const { return withDepthRangeFitted(cam_.camera, scene_.bounds); }

void ViewerModel::restart() {
  try {
    validate(cam_.camera.view, "the panel's camera");
    validateLensEffects(cam_.camera, "the panel's camera");
    if (!(cam_.camera.lens.apertureRadius >= 0.0) || !std::isfinite(cam_.camera.lens.apertureRadius))
      throw InputError("the panel's camera: aperture radius must be 0 (a pinhole) or positive");
    plan_ = makeFramePlan(scene_, cam_.camera, size_, planOptions_);
    lastGood_ = cam_;
    error_.clear();
  } catch (const InputError& e) {
    reportError(e.what());
    cam_ = lastGood_;
    plan_ = makeFramePlan(scene_, cam_.camera, size_, planOptions_);
  }
  budget_.restart();
  dirty_ = false;
}

double ViewerModel::diagramApertureScale() const { return enlargeAperture_ ? readableApertureScale(cam_.camera) : 1.0; }

std::vector<DiagramLine> ViewerModel::diagram(const std::vector<LensSample>& samples, int samplesDone) const {
  DiagramStyle style;
  style.apertureScale = diagramApertureScale();
  return lectureDiagram(cam_.camera, samples, samplesDone, style);
}

}  // namespace lenslab::view
