#include "viewer/gl_context.h"

#include <glad/gl.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace radmesh {

void loadGlFunctions(GlProcLoader load, const char* contextName) {
  const int version = gladLoadGL(load);
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw std::runtime_error(std::string(contextName) +
                             ": OpenGL 3.3 core is not available (got " +
                             std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                             std::to_string(GLAD_VERSION_MINOR(version)) +
                             "); install Mesa (libgl1-mesa-dri, libosmesa6) or update the driver");
}

Image captureFramebuffer(glm::ivec2 size) {
  Image image{size.x, size.y, std::vector<std::uint8_t>(static_cast<size_t>(size.x) * size.y * 4)};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's rows start at the bottom; images start at the top.
  const size_t rowBytes = static_cast<size_t>(size.x) * 4;
  std::vector<std::uint8_t> row(rowBytes);
  for (int y = 0; y < size.y / 2; ++y) {
    std::uint8_t* a = image.rgba.data() + y * rowBytes;
    std::uint8_t* b = image.rgba.data() + (size.y - 1 - y) * rowBytes;
    std::memcpy(row.data(), a, rowBytes);
    std::memcpy(a, b, rowBytes);
    std::memcpy(b, row.data(), rowBytes);
  }
  return image;
}

}  // namespace radmesh
