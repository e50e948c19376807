#pragma once
// An offscreen OpenGL core context in a user buffer (Mesa's OSMesa, llvmpipe): no display needed.
#include <cstdint>
#include <vector>

#include "viewer/gl_context.h"

struct osmesa_context;

namespace radmesh {

class OsMesaContext final : public GlContext {
 public:
  explicit OsMesaContext(glm::ivec2 size);  // throws std::runtime_error if OSMesa cannot create it
  ~OsMesaContext() override;
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void makeCurrent() override;
  glm::ivec2 framebufferSize() const override { return size_; }
  void resize(glm::ivec2 size);  // takes effect at once if current, else at the next makeCurrent

 private:
  osmesa_context* context_ = nullptr;
  glm::ivec2 size_;
  std::vector<std::uint8_t> buffer_;  // RGBA8, the colour buffer OSMesa draws into
};

}  // namespace radmesh
