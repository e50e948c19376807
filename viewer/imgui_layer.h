#pragma once
// Dear ImGui on a GLFW window: the GLFW platform backend from Debian's libimgui, and the OpenGL 3
// renderer backend compiled here against our loader (see CMakeLists.txt).
struct GLFWwindow;

namespace radmesh {

class ImGuiLayer {
 public:
  explicit ImGuiLayer(GLFWwindow* window);  // the window's context must be current
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void beginFrame();
  void endFrame();  // draws the frame's widgets over whatever the renderer drew

  bool wantsMouse() const;     // the pointer is over a widget: not for the camera
  bool wantsKeyboard() const;  // a widget has focus: keys are not for walking
};

}  // namespace radmesh
