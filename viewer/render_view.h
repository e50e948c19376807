#pragma once
// Where the eye is and where it looks: what the window's walkthrough camera and the CLI's
// --camera/--look/--fov both hand to the renderer.
#include <glm/glm.hpp>

namespace radmesh {

struct RenderView {
  glm::dvec3 eye{0.0, 0.0, 0.0};   // metres
  glm::dvec3 look{0.0, 1.0, 0.0};  // a point the eye looks at
  glm::dvec3 up{0.0, 0.0, 1.0};
  double fovYDeg = 60.0;           // vertical field of view
  double nearM = 0.02;
  double farM = 1000.0;
};

// Throws std::invalid_argument when the view is degenerate (eye on the look point, look along
// up, a field of view outside (0, 180), or near/far not 0 < near < far).
void validateView(const RenderView& view);

// Clip-space transform for a framebuffer of the given width / height.
glm::mat4 viewProjectionMatrix(const RenderView& view, double aspect);

}  // namespace radmesh
