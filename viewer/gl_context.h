#pragma once
// Where the renderer draws: a window (window_context.h) or an offscreen buffer (osmesa_context.h).
// The renderer never knows which. Each context loads the GL entry points through its own
// getProcAddress when made current: OSMesa exports gl* symbols that do nothing in a GLX setting
// and vice versa, so calling GL through a loader filled per context is what makes both work.
#include <glm/vec2.hpp>

#include "viewer/image.h"

namespace radmesh {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void makeCurrent() = 0;  // also (re)loads the GL entry points for this context
  virtual glm::ivec2 framebufferSize() const = 0;
};

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Fills the loader from `load`; throws std::runtime_error naming `contextName` when the context
// does not give OpenGL 3.3 core.
void loadGlFunctions(GlProcLoader load, const char* contextName);

// The current context's colour buffer (call before presenting), top row first.
Image captureFramebuffer(glm::ivec2 size);

}  // namespace radmesh
