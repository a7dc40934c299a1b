#pragma once
// The interactive view's state and its rules, without a window (no GL, GLFW or Dear ImGui), so
// that they are unit-tested: the camera being edited and the last valid one to go back to, the
// plan options and the frame plan, the progressive sample budget, and the outside view's orbit
// camera. Viewer (the GLFW + Dear ImGui shell, Viewer.h) turns input and panel edits into calls
// here, and renders what this holds.
#include "camera/Camera.h"
#include "camera/FocusOnPixel.h"
#include "camera/ImageSize.h"
#include "camera/PhysicalCamera.h"
#include "lens/AperturePattern.h"
#include "plan/FramePlan.h"
#include "scene/Scene.h"
#include "view/LectureDiagram.h"
#include "view/Navigation.h"

#include <glm/glm.hpp>

#include <chrono>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::view {

// How many aperture samples a frame adds: as many as the last measured cost per sample allows in
// the frame's time budget (--frame-budget-ms), so that the window stays responsive; never fewer
// than one, so that a slow GPU still converges; never more than remain.
class SampleBudget {
 public:
  explicit SampleBudget(double frameBudgetMs) : frameBudgetMs_(frameBudgetMs) {}

  int samplesForFrame(int remaining) const;  // 0 when none remain
  // A frame added `added` samples in `ms` (GPU work finished): the estimate for the next frame.
  // `complete`: that was the last sample of the accumulation.
  void measured(int added, double ms, bool complete);
  // A new accumulation: its time and convergence start again. The cost per sample stays as the
  // first frame's estimate (the scene did not change).
  void restart();

  double msPerSample() const { return msPerSample_; }
  double accumulationMs() const { return accumulationMs_; }      // scene passes of this accumulation
  double convergedAfterMs() const { return convergedAfterMs_; }  // wall time since restart; < 0: not yet

 private:
  using Clock = std::chrono::steady_clock;
  double frameBudgetMs_;
  double msPerSample_ = 0.0;  // 0: not measured yet (the first frame adds one sample)
  double accumulationMs_ = 0.0;
  Clock::time_point restartTime_ = Clock::now();
  double convergedAfterMs_ = -1.0;
};

// The outside view's camera: a pinhole orbiting the point halfway between the lecture camera's
// PRP and its focus pivot, at a distance in proportion to the camera's size, so that the diagram
// of the camera (PRP, window, aperture) stays in sight wherever the camera goes.
struct OutsideOrbit {
  double azimuthRadians = 0.8;    // from behind the camera toward its right
  double elevationRadians = 0.5;  // above the horizon
  double zoom = 0.8;              // the distance, in multiples of 2.2 × the camera's extent

  void orbit(double azimuthStep, double elevationStep);  // elevation kept off the poles (±1.5)
  void zoomBy(double wheelSteps);                        // 0.9× per step in, within [0.05, 50]
  Camera cameraFor(const Camera& lecture, double aspect) const;
};

class ViewerModel {
 public:
  // `scene` must outlive the model. Errors are written to `errorLog` as one line each, as well as
  // kept for the panel.
  ViewerModel(const Scene& scene, EditableCamera camera, ImageSize size, PlanOptions planOptions, double frameBudgetMs,
              std::ostream& errorLog);

  const EditableCamera& camera() const { return cam_; }
  // The camera as rendered: its open near/far fitted to the scene (camera/DepthRange.h).
  Camera renderCamera() const;
  ImageSize size() const { return size_; }
  const PlanOptions& planOptions() const { return planOptions_; }
  const FramePlan& plan() const { return plan_; }  // of the last restart
  // The plan again, from the blur the renderer's pre-pass saw (plan/VisibleBlur.h): the auto count
  // and the tiles' minimums follow what is in view, not the scene's bounds.
  void replanWith(const VisibleBlur& visible);
  // Whether a pre-pass would change the plan: a lens, and a count chosen by the plan.
  bool wantsVisibleBlur() const;

  // ---- edits: each marks the accumulation for a restart, which checks the camera ----
  void orbit(double yawRadians, double pitchRadians);       // about the focus pivot
  void lookAround(double yawRadians, double pitchRadians);  // about the PRP
  // Flying: `direction` (right, up, forward; components in [−1, 1]) for `seconds`, at half the
  // focus distance per second, four times that when `fast`; the wheel moves a tenth of the focus
  // distance per step. Both scale with the scene as the camera sees it.
  void fly(glm::dvec3 direction, double seconds, bool fast);
  void moveForward(double wheelSteps);
  void editLecture(const Camera& camera);             // a lecture-form edit: the physical form is dropped
  void refocus(double distance);                      // keeps the field of view; invalid: reported, ignored
  void editPhysical(const PhysicalCamera& physical);  // keeps the lens effects and calibrated size
  // A perspective camera with the PRP over the window centre can be described as a lens.
  bool canDescribeAsLens() const;
  void describeAsLens();                             // a 35 mm-wide sensor
  void editLensEffects(const LensEffects& effects);  // invalid: reported, ignored
  void setPlanOptions(const PlanOptions& options);
  // Focuses on what image pixel `pixel` shows; returns the new focus distance. Throws InputError
  // (nothing there, outside the image) as --focus-at does.
  // `asked`: the option that asked for it (--focus-at, --click), which an error names.
  double focusAt(glm::dvec2 pixel, const DepthAtPixel& depthAt, const std::string& asked);
  // The same for a click in the window: an error is reported (in the click's words), not thrown.
  std::optional<double> clickAt(glm::dvec2 pixel, const DepthAtPixel& depthAt);
  std::optional<double> lastFocusDistance() const { return focusDistance_; }  // the last click's

  bool needsRestart() const { return dirty_; }
  // Checks the camera: when an edit made it invalid, the error is reported and the camera goes
  // back to the last valid one. Then makes the frame plan and restarts the sample budget.
  void restart();

  void reportError(const std::string& message);
  const std::string& error() const { return error_; }  // the last error; cleared by a valid restart

  SampleBudget& budget() { return budget_; }
  const SampleBudget& budget() const { return budget_; }

  OutsideOrbit& outside() { return outside_; }
  Camera outsideCamera(double aspect) const { return outside_.cameraFor(cam_.camera, aspect); }
  // The lecture diagram of the camera, drawn over the outside view. The aperture (millimetres) is
  // drawn enlarged, beside a window of metres, unless asked not to.
  bool enlargeAperture() const { return enlargeAperture_; }
  void setEnlargeAperture(bool enlarge) { enlargeAperture_ = enlarge; }
  double diagramApertureScale() const;  // 1 when not enlarged
  std::vector<DiagramLine> diagram(const std::vector<LensSample>& samples, int samplesDone) const;

 private:
  const Scene& scene_;
  std::ostream& errorLog_;
  ImageSize size_;
  PlanOptions planOptions_;
  EditableCamera cam_;
  EditableCamera lastGood_;  // what to go back to when an edit makes the camera invalid
  std::string baseSource_;   // where the camera came from, before any click
  FramePlan plan_;
  bool dirty_ = true;  // the accumulation must restart
  std::optional<double> focusDistance_;
  std::string error_;
  SampleBudget budget_;
  OutsideOrbit outside_;
  bool enlargeAperture_ = true;
};

}  // namespace lenslab::view
