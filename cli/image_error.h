#pragma once
// Accuracy across meshes: solutions on different patch meshes cannot be compared patch by patch,
// so they are compared as what a user sees, pictures from fixed cameras at one fixed exposure.
#include <memory>
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh::cli {

class ImageErrorProbe {
 public:
  // Cameras: the walkthrough's start view, and in a closed scene the view from the opposite corner.
  explicit ImageErrorProbe(const Scene& scene);
  ~ImageErrorProbe();
  ImageErrorProbe(const ImageErrorProbe&) = delete;
  ImageErrorProbe& operator=(const ImageErrorProbe&) = delete;

  // False when radmesh was built without the viewer: error() then gives -1.
  static bool available();
  int cameraCount() const;

  // Renders the reference pictures and fixes the exposure to the reference's automatic one.
  void setReference(const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity);
  // Mean over the cameras of the RMSE against the reference pictures, in 8-bit sRGB levels. The
  // display mesh is built again whenever the patches differ from the last call's.
  double error(const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace radmesh::cli
