#include "viewer/window_context.h"

#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace radmesh {

namespace {

std::string lastGlfwError;

void rememberGlfwError(int, const char* description) { lastGlfwError = description; }

}  // namespace

WindowContext::WindowContext(const std::string& title, glm::ivec2 size) {
  glfwSetErrorCallback(rememberGlfwError);
  if (!glfwInit())
    throw std::runtime_error("cannot open a window: " + lastGlfwError +
                             " (no display? run under xvfb-run, or use `radmesh render` offscreen)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core window: " + lastGlfwError);
  }
  makeCurrent();
  glfwSwapInterval(1);
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowContext::makeCurrent() {
  glfwMakeContextCurrent(window_);
  loadGlFunctions(glfwGetProcAddress, "GLFW window");
}

glm::ivec2 WindowContext::framebufferSize() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_); }
void WindowContext::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void WindowContext::swapBuffers() { glfwSwapBuffers(window_); }

}  // namespace radmesh
