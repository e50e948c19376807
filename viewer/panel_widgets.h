#pragma once
// Small ImGui widgets the panel's tabs share (viewer/panel*.cpp).
#include <imgui.h>

namespace radmesh {

// True while the value changes.
inline bool sliderDouble(const char* label, double* value, double min, double max, const char* format,
                        ImGuiSliderFlags flags = ImGuiSliderFlags_None) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, value, &min, &max, format, flags);
}

// A greyed remark that wraps at the panel's edge.
inline void note(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

// A failure, in red, that wraps at the panel's edge.
inline void failureText(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

}  // namespace radmesh
