#pragma once
// A resizable GLFW window with an OpenGL 3.3 core context and vsync.
#include <string>

#include "viewer/gl_context.h"

struct GLFWwindow;

namespace radmesh {

class WindowContext final : public GlContext {
 public:
  // Throws std::runtime_error when there is no display or no OpenGL 3.3 core.
  WindowContext(const std::string& title, glm::ivec2 size);
  ~WindowContext() override;
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  void makeCurrent() override;
  glm::ivec2 framebufferSize() const override;

  GLFWwindow* window() const { return window_; }
  bool shouldClose() const;
  void requestClose();
  void swapBuffers();

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace radmesh
