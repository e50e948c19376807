#pragma once
// Keys and mouse of a GLFW window as walkthrough motion: WASD or arrows walk, Q/E (or Page
// Down/Up) lower and raise the eye, Shift runs, dragging with the left button looks around.
#include "viewer/camera.h"

struct GLFWwindow;

namespace radmesh {

class WalkInputReader {
 public:
  // `keysFree` / `mouseFree`: whether the panel leaves keys and pointer to the walk.
  WalkInput read(GLFWwindow* window, bool keysFree, bool mouseFree);

 private:
  bool dragging_ = false;
  double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace radmesh
