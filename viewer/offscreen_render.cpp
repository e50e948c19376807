#include "viewer/offscreen_render.h"

#include <glad/gl.h>

#include "viewer/exposure.h"
#include "viewer/osmesa_context.h"
#include "viewer/renderer.h"

namespace radmesh {

OffscreenRenderer::OffscreenRenderer(const DisplayMesh& mesh, glm::ivec2 size)
    : mesh_(mesh), context_(std::make_unique<OsMesaContext>(size)), renderer_(std::make_unique<Renderer>()) {
  renderer_->setMesh(mesh);
}

OffscreenRenderer::~OffscreenRenderer() {
  context_->makeCurrent();  // the renderer's GL objects belong to this context
  renderer_.reset();
}

Image OffscreenRenderer::render(const std::vector<Rgb>& vertexB, const RenderView& view,
                                const OffscreenShading& shading) {
  validateView(view);
  context_->makeCurrent();
  renderer_->setVertexRadiosity(vertexB);
  renderer_->setHighlightedPatches(shading.highlightedPatches);
  const glm::ivec2 size = context_->framebufferSize();
  const double exposure = shading.exposure ? *shading.exposure : autoExposure(mesh_, vertexB);
  renderer_->draw(view, size, Shading{exposure, true});
  glFinish();
  return captureFramebuffer(size);
}

void renderToPng(const DisplayMesh& mesh, const std::vector<Rgb>& vertexB, const RenderView& view,
                 int width, int height, const std::string& png, const OffscreenShading& shading) {
  OffscreenRenderer renderer(mesh, {width, height});
  writePng(renderer.render(vertexB, view, shading), png);
}

}  // namespace radmesh
