#include "viewer/osmesa_context.h"

#include <glad/gl.h>  // before osmesa.h, which includes GL/gl.h
#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace radmesh {

namespace {

void checkSize(glm::ivec2 size) {
  if (size.x < 1 || size.y < 1 || size.x > 16384 || size.y > 16384)
    throw std::runtime_error("offscreen size " + std::to_string(size.x) + "x" +
                             std::to_string(size.y) + " is outside 1..16384 per side");
}

}  // namespace

OsMesaContext::OsMesaContext(glm::ivec2 size) : size_(size) {
  checkSize(size);
  // Asking for 3.3 core yields llvmpipe's newest core profile, which includes 3.3.
  const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA,         OSMESA_DEPTH_BITS, 24,
                            OSMESA_PROFILE,      OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION,
                            3,                   OSMESA_CONTEXT_MINOR_VERSION,
                            3,                   0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context_)
    throw std::runtime_error(
        "OSMesa could not create an OpenGL 3.3 core context (is libosmesa6 from Mesa installed?)");
  makeCurrent();
}

OsMesaContext::~OsMesaContext() { OSMesaDestroyContext(context_); }

void OsMesaContext::makeCurrent() {
  buffer_.resize(static_cast<size_t>(size_.x) * size_.y * 4);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, size_.x, size_.y))
    throw std::runtime_error("OSMesa could not make its context current at " +
                             std::to_string(size_.x) + "x" + std::to_string(size_.y));
  loadGlFunctions(OSMesaGetProcAddress, "OSMesa");
}

void OsMesaContext::resize(glm::ivec2 size) {
  checkSize(size);
  size_ = size;
  if (OSMesaGetCurrentContext() == context_) makeCurrent();
}

}  // namespace radmesh
