#include "viewer/walk_input.h"

#include <GLFW/glfw3.h>

namespace radmesh {

namespace {

constexpr double kRadiansPerPixel = 0.004;
constexpr double kRunFactor = 3.0;

double axis(GLFWwindow* window, int plusA, int plusB, int minusA, int minusB) {
  auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
  return (down(plusA) || down(plusB) ? 1.0 : 0.0) - (down(minusA) || down(minusB) ? 1.0 : 0.0);
}

}  // namespace

WalkInput WalkInputReader::read(GLFWwindow* window, bool keysFree, bool mouseFree) {
  WalkInput input;
  if (keysFree) {
    const bool run = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                     glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    const double pace = run ? kRunFactor : 1.0;
    input.forward = pace * axis(window, GLFW_KEY_W, GLFW_KEY_UP, GLFW_KEY_S, GLFW_KEY_DOWN);
    input.right = pace * axis(window, GLFW_KEY_D, GLFW_KEY_RIGHT, GLFW_KEY_A, GLFW_KEY_LEFT);
    input.rise = pace * axis(window, GLFW_KEY_E, GLFW_KEY_PAGE_UP, GLFW_KEY_Q, GLFW_KEY_PAGE_DOWN);
  }
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  // A drag that starts over the panel belongs to the panel until the button is let go.
  if (pressed && (dragging_ || mouseFree)) {
    if (dragging_) {
      input.yawRad = -kRadiansPerPixel * (x - lastX_);
      input.pitchRad = -kRadiansPerPixel * (y - lastY_);
    }
    dragging_ = true;
  } else {
    dragging_ = false;
  }
  lastX_ = x;
  lastY_ = y;
  return input;
}

}  // namespace radmesh
