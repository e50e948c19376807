#include "viewer/offscreen_render.h"

#include <glad/gl.h>

#include <cmath>

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

long long backgroundPixels(const Image& image) {
  long long count = 0;
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    bool background = true;
    for (int c = 0; c < 3; ++c)
      background = background && std::abs(image.rgba[i + c] - std::lround(255.0 * kBackgroundRgb[c])) <= 1;
    count += background;
  }
  return count;
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
