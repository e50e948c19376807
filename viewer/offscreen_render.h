#pragma once
// Rendering with no display: the window's renderer in an OSMesa context. Used by `radmesh render`
// and the golden-image tests.
#include <glm/vec2.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/bake/display_radiosity.h"
#include "viewer/image.h"
#include "viewer/render_view.h"

namespace radmesh {

class OsMesaContext;
class Renderer;

struct OffscreenShading {
  std::optional<double> exposure;  // linear factor; unset: autoExposure of the frame's radiosity
  std::vector<int> highlightedPatches;
};

// One context and one renderer kept across frames of the same mesh (streaming, timing).
class OffscreenRenderer {
 public:
  OffscreenRenderer(const DisplayMesh& mesh, glm::ivec2 size);  // throws std::runtime_error
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  Image render(const std::vector<Rgb>& vertexB, const RenderView& view,
               const OffscreenShading& shading = {});

 private:
  DisplayMesh mesh_;  // for the automatic exposure
  std::unique_ptr<OsMesaContext> context_;
  std::unique_ptr<Renderer> renderer_;
};

// Pixels of the clear colour (within a level of it, as OSMesa rounds): where no surface was drawn.
long long backgroundPixels(const Image& image);

// Renders one frame and writes it as PNG; throws std::runtime_error or std::invalid_argument
// with a message naming what is wrong.
void renderToPng(const DisplayMesh& mesh, const std::vector<Rgb>& vertexB, const RenderView& view,
                 int width, int height, const std::string& png, const OffscreenShading& shading = {});

}  // namespace radmesh
