#include "viewer/render_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>

namespace radmesh {

void validateView(const RenderView& view) {
  const glm::dvec3 direction = view.look - view.eye;
  if (glm::length(direction) < 1e-9)
    throw std::invalid_argument("the camera position equals the look point; move one of them");
  if (glm::length(glm::cross(glm::normalize(direction), glm::normalize(view.up))) < 1e-6)
    throw std::invalid_argument("the camera looks straight along the up axis; tilt the look point");
  if (!(view.fovYDeg > 0.0 && view.fovYDeg < 180.0))
    throw std::invalid_argument("field of view must lie strictly between 0 and 180 degrees");
  if (!(view.nearM > 0.0 && view.nearM < view.farM))
    throw std::invalid_argument("clip planes need 0 < near < far");
}

glm::mat4 viewProjectionMatrix(const RenderView& view, double aspect) {
  const glm::dmat4 lookAt = glm::lookAt(view.eye, view.look, view.up);
  const glm::dmat4 projection =
      glm::perspective(glm::radians(view.fovYDeg), aspect, view.nearM, view.farM);
  return glm::mat4(projection * lookAt);
}

}  // namespace radmesh
