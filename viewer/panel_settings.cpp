// The panel's Parameters and View tabs: what the user sets (the solve's options, the walk's view).
#include <imgui.h>

#include <algorithm>

#include "parallel/thread_pool.h"
#include "solver/scene/scene_error.h"
#include "viewer/panel.h"
#include "viewer/panel_widgets.h"

namespace radmesh {

namespace {

// A solve parameter restarts the solve once the user lets go of it, not at every pixel dragged.
bool released() { return ImGui::IsItemDeactivatedAfterEdit(); }

template <class Enum, size_t N>
bool comboOf(const char* label, Enum* value, const Enum (&choices)[N]) {
  bool changed = false;
  if (ImGui::BeginCombo(label, toString(*value))) {
    for (Enum choice : choices)
      if (ImGui::Selectable(toString(choice), choice == *value)) {
        changed = choice != *value;
        *value = choice;
      }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

void Panel::drawParameters(SolverThread& solver) {
  SolveOptions& o = edited_.options;
  bool changed = false;
  ImGui::PushItemWidth(200.0f);
  changed |= comboOf("back end", &o.backend, {Backend::Native, Backend::Mesh});
  changed |= comboOf("projection", &o.projection, {Projection::Plane, Projection::Hemicube, Projection::Analytic});
  changed |= comboOf("mapping (mesh)", &o.mapping,
                     {MappingKind::Hierarchical, MappingKind::CutAndStack, MappingKind::Adaptive});
  ImGui::SliderInt("resolution N", &o.resolution, 16, 2048, "%d", ImGuiSliderFlags_Logarithmic);
  changed |= released();
  sliderDouble("ratio", &o.ratio, 0.5, 10.0, "%.2f");
  changed |= released();
  ImGui::SliderInt("shooters k", &o.shooters, 1, 64);
  changed |= released();
  sliderDouble("cell m", &edited_.cellM, 0.02, 2.0, "%.3f", ImGuiSliderFlags_Logarithmic);
  changed |= released();
  ImGui::SliderInt("host threads", &o.threads, 0, ThreadPool::mostUseful(), o.threads == 0 ? "0: every core but one" : "%d");
  changed |= released();
  changed |= ImGui::Checkbox("ambient term (display only)", &o.ambient);
  // The stopping rule applies to the solve under way: no restart.
  sliderDouble("until unshot (0: off)", &o.untilUnshot, 0.0, 0.5, "%.3f", ImGuiSliderFlags_Logarithmic);
  bool stoppingRuleChanged = released();
  sliderDouble("until C (1: off)", &o.until, 0.1, 1.0, "%.4f");
  stoppingRuleChanged |= released();
  ImGui::PopItemWidth();
  note("the stopping rule applies to the solve under way; any other change restarts it");
  if (changed || stoppingRuleChanged) {
    try {
      validateOptions(o);
      parameterError_.clear();
      if (changed)
        solver.restart(edited_);
      else
        solver.setStoppingRule(o.until, o.untilUnshot);
    } catch (const OptionError& e) {
      parameterError_ = e.what();
    }
  }
  if (!parameterError_.empty()) ImGui::TextWrapped("not applied: %s", parameterError_.c_str());
}

void Panel::drawView(WalkCamera& camera, ViewSettings& view, bool solving) {
  ImGui::PushItemWidth(200.0f);
  exposureSpan_ = exposureSliderSpan(view.exposureStops, exposureSpan_);
  if (sliderDouble("exposure EV", &view.exposureStops, exposureSpan_.low, exposureSpan_.high, "%.2f")) {
    // Ctrl+click types a value past the span: as far as --exposure takes.
    view.exposureStops = std::clamp(view.exposureStops, -kMaxExposureStops, kMaxExposureStops);
    view.autoExposure = false;
  }
  ImGui::SameLine();
  if (ImGui::Button("Auto")) view.autoExposure = true;
  ImGui::Checkbox("follow auto exposure", &view.autoExposure);
  if (solving) ImGui::Checkbox("highlight last shooters", &view.highlightShooters);
  if (solving) ImGui::Checkbox("draw only the rooms in sight through doors", &view.cullCells);
  const WalkCamera::Range speed = camera.speedRange(), eye = camera.eyeHeightRange();
  sliderDouble("speed m/s", &camera.speedMps, speed.low, speed.high, "%.3g", ImGuiSliderFlags_Logarithmic);
  // A value typed with Ctrl+click may pass the ends: no lower than the walk goes, higher as it does.
  if (sliderDouble("eye height m", &camera.eyeHeightM, eye.low, eye.high, "%.3g"))
    camera.eyeHeightM = std::max(camera.eyeHeightM, eye.low);
  sliderDouble("field of view", &camera.fovYDeg, 20.0, 110.0, "%.0f deg");
  ImGui::PopItemWidth();
  note("WASD/arrows walk, Q/E lower/raise, Shift runs");
  note("drag to look around, Esc quits");
}

}  // namespace radmesh
