#pragma once
// The one renderer of both contexts: Gouraud shading of per-vertex display radiosity, linear to
// sRGB with an exposure factor, and the last shooters highlighted. Needs a current GL context
// (see gl_context.h) for its whole life.
#include <glm/vec2.hpp>

#include <vector>

#include "solver/bake/display_radiosity.h"
#include "viewer/render_view.h"

namespace radmesh {

// The clear colour, linear RGB written as it is: what shows where no surface covers a pixel.
inline constexpr float kBackgroundRgb[3] = {0.02f, 0.02f, 0.03f};

struct Shading {
  double exposure = 1.0;        // linear factor applied to radiosity (W/m^2) before sRGB encoding
  bool highlightShooters = true;
};

class Renderer {
 public:
  Renderer();  // compiles the shaders; throws std::runtime_error with the GL log on failure
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // New geometry; radiosity starts at zero and nothing is highlighted.
  void setMesh(const DisplayMesh& mesh);
  // One value per mesh vertex (vertexRadiosity in solver/bake/display_radiosity.h).
  void setVertexRadiosity(const std::vector<Rgb>& vertexB);
  // Patches (indices into the solver's patches) drawn tinted, e.g. the last iteration's shooters.
  void setHighlightedPatches(const std::vector<int>& patches);
  // Groups the triangles by the cell of their patch (kOutsideCell, or a cell below `cells`), so
  // that setVisibleCells can leave cells out. Until the next setMesh.
  void setCells(const std::vector<int>& cellOfPatch, int cells);
  // Per cell: whether it is drawn; empty draws every cell. Patches facing no cell are always drawn.
  void setVisibleCells(std::vector<bool> visible);

  // Clears and draws into the current context's framebuffer.
  void draw(const RenderView& view, glm::ivec2 framebufferSize, const Shading& shading);

 private:
  void drawVisibleCells() const;

  unsigned program_ = 0;
  unsigned vertexArray_ = 0;
  unsigned positionBuffer_ = 0, normalBuffer_ = 0, radiosityBuffer_ = 0;
  unsigned indexBuffer_ = 0, highlightIndexBuffer_ = 0;
  int viewProjectionLocation_ = -1, eyeLocation_ = -1, exposureLocation_ = -1;
  int tintLocation_ = -1, tintAmountLocation_ = -1;
  size_t vertexCount_ = 0;
  // The mesh's centre, taken off every position before it becomes a float (and off the view): a
  // model 1e7 m from the origin would otherwise be drawn at whole metres.
  Vec3 origin_{0.0};
  double radiosityScale_ = 1.0;  // the uploaded radiosity is B / radiosityScale_
  size_t indexCount_ = 0;
  size_t highlightIndexCount_ = 0;
  std::vector<unsigned> indices_;          // kept to build the highlight's index list
  std::vector<size_t> firstTriangleOfPatch_;  // triangles sorted by patch: CSR offsets
  std::vector<unsigned> trianglesByPatch_;
  std::vector<size_t> firstIndexOfCell_;  // with cells: the index buffer by cell, the outside last
  std::vector<bool> visibleCells_;
};

}  // namespace radmesh
