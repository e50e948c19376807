#include "cli/image_error.h"

#include <algorithm>
#include <stdexcept>

#if RADMESH_HAS_VIEWER
#include "solver/bake/display_radiosity.h"
#include "viewer/camera.h"
#include "viewer/exposure.h"
#include "viewer/offscreen_render.h"
#endif

namespace radmesh::cli {

#if RADMESH_HAS_VIEWER

namespace {
constexpr glm::ivec2 kSize{320, 240};  // enough pixels for shading gradients, cheap to draw

// Adaptive elements split in place, and another solve's may sit at the same address: the mesh is
// known by what it holds.
bool sameMesh(const std::vector<Patch>& a, const std::vector<Patch>& b) {
  return std::ranges::equal(a, b, [](const Patch& p, const Patch& q) {
    return p.vertexCount == q.vertexCount && p.vertices == q.vertices && p.material == q.material;
  });
}
}

struct ImageErrorProbe::State {
  std::vector<RenderView> views;
  double exposure = 1.0;
  std::vector<Image> reference;
  std::vector<Patch> mesh;  // the patches renderer was built for
  DisplayMesh display;
  std::unique_ptr<OffscreenRenderer> renderer;

  // `fixExposure`: take this frame's automatic exposure for every picture from now on.
  std::vector<Image> render(const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity,
                            bool fixExposure) {
    if (!renderer || !sameMesh(mesh, patches)) {
      display = buildDisplayMesh(patches);
      renderer = std::make_unique<OffscreenRenderer>(display, kSize);
      mesh = patches;
    }
    const std::vector<Rgb> vertexB = vertexRadiosity(display, displayRadiosity);
    if (fixExposure) exposure = autoExposure(display, vertexB);
    std::vector<Image> images;
    for (const RenderView& view : views) images.push_back(renderer->render(vertexB, view, {exposure, {}}));
    return images;
  }
};

ImageErrorProbe::ImageErrorProbe(const Scene& scene) : state_(std::make_unique<State>()) {
  const SceneFrame frame = sceneFrame(scene);
  const WalkCamera camera(frame);
  const RenderView start = camera.view();
  state_->views.push_back(start);
  if (!camera.looksInFromOutside()) {  // the opposite corner, same height, looking at the same point
    RenderView opposite = start;
    const glm::dvec3 centre = 0.5 * (frame.boundsMin + frame.boundsMax);
    for (int axis = 0; axis < 3; ++axis)
      if (axis != frame.upAxis) opposite.eye[axis] = 2.0 * centre[axis] - start.eye[axis];
    opposite.look = start.look;
    for (int axis = 0; axis < 3; ++axis)
      if (axis != frame.upAxis) opposite.look[axis] = 2.0 * centre[axis] - start.look[axis];
    state_->views.push_back(opposite);
  }
}

bool ImageErrorProbe::available() { return true; }
int ImageErrorProbe::cameraCount() const { return static_cast<int>(state_->views.size()); }

void ImageErrorProbe::setReference(const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity) {
  state_->reference = state_->render(patches, displayRadiosity, true);
}

double ImageErrorProbe::error(const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity) {
  if (state_->reference.empty()) throw std::logic_error("ImageErrorProbe: setReference comes first");
  const std::vector<Image> images = state_->render(patches, displayRadiosity, false);
  double sum = 0.0;
  for (size_t k = 0; k < images.size(); ++k) sum += imageRmse(images[k], state_->reference[k]);
  return sum / static_cast<double>(images.size());
}

#else

struct ImageErrorProbe::State {};
ImageErrorProbe::ImageErrorProbe(const Scene&) {}
bool ImageErrorProbe::available() { return false; }
int ImageErrorProbe::cameraCount() const { return 0; }
void ImageErrorProbe::setReference(const std::vector<Patch>&, const std::vector<Rgb>&) {}
double ImageErrorProbe::error(const std::vector<Patch>&, const std::vector<Rgb>&) { return -1.0; }

#endif

ImageErrorProbe::~ImageErrorProbe() = default;

}  // namespace radmesh::cli
