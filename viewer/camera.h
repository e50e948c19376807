#pragma once
// The walkthrough camera: walks on the scene's floor at an eye height, turns with the mouse.
// Knows nothing of GLFW; the window turns keys and mouse motion into a WalkInput.
#include <algorithm>
#include <optional>

#include <glm/vec2.hpp>

#include "viewer/render_view.h"
#include "viewer/scene_frame.h"

namespace radmesh {

struct WalkInput {
  // In multiples of the walking speed: -1..1, more when running.
  double forward = 0.0;  // back / forward
  double right = 0.0;    // left / right
  double rise = 0.0;     // lowers / raises the eye height
  double yawRad = 0.0;   // turn left (positive) about the up axis
  double pitchRad = 0.0; // look up (positive)
};

// --camera and --look (radmesh render's and radmesh-view's), in the coordinates of the file shown:
// a scene's as read (metres after --units; --up does not turn them), a bake's y-up ones as it was
// written, which are not those of the scene it was baked from (docs/scene-formats.md#bakes).
struct ViewStart {
  std::optional<glm::dvec3> eye{};   // none: the walkthrough's own start
  std::optional<glm::dvec3> look{};  // none: the start's own direction; with an eye, the bounds' centre
};

class WalkCamera {
 public:
  // Starts inside the scene, near a corner of the bounds, the eye 1.6 m above the lowest floor
  // (lower in a room under 2.7 m), looking level the longest way clear (stepIntoFreeSpace): the
  // corner of least across and along (upFrame's), unless the furniture stands on that side
  // (cornerFacingFurniture). A scene open on one side (a Cornell box) is looked into through that
  // side from outside instead, and so is a model with no free space to stand in (a luminaire, a
  // chair: lookFromOutside). A building drawn at an angle to the axes (frame.planTurn) starts as
  // it would drawn along them.
  explicit WalkCamera(const SceneFrame& frame);

  // The corner to start in, as the signs of across and along (-1 least, 1 greatest): the least,
  // unless the furniture stands much nearer to it than to the corner farthest from the furniture;
  // then that one, so that the start view looks at the furniture, not away (office3's desk).
  static glm::dvec2 cornerFacingFurniture(const SceneFrame& frame);

  // Moves to a room: `reach` of its extent from the centre of its bounds towards the corner given
  // as signs of `across` and `along` (the least corner by default), looking level at the centre;
  // the eye height is kept.
  void standIn(const Vec3& boundsMin, const Vec3& boundsMax, glm::dvec2 corner = {-1.0, -1.0}, double reach = 0.35);
  // A cell's bounds are its free space's voxels', up to a voxel past its walls on every side: 0.35
  // of them from the centre stood in the spine's outer wall on building:2x2.
  static constexpr double kCellReach = 0.25;
  // Moves the start to `start`, keeping fovYDeg. Throws OptionError naming the flags given
  // (--fov too when `fovGiven`), or the walkthrough's start when none is, if they make no view
  // (validateView): an eye on the look point, a look straight along the up axis.
  void startFrom(const ViewStart& start, bool fovGiven = false);
  // Whether it started outside, looking in through an open side or at a model with no room in it.
  bool looksInFromOutside() const { return outside_; }
  // Whether it started where it was told (startFrom an eye or a look): a cells solve leaves it there.
  bool startGiven() const { return startGiven_; }
  void update(const WalkInput& input, double dtSeconds);
  RenderView view() const;

  // The panel's slider ranges, which follow the model as the pace does: metres in a room, a
  // millimetre model's own scale in one (a 0.05 m/s floor jumped past its whole size).
  struct Range {
    double low = 0.0, high = 0.0;
  };
  Range speedRange() const { return {std::min(0.05, 0.01 * sizeM()), std::max(10.0, sizeM())}; }
  Range eyeHeightRange() const { return {lowestEyeM(), highestEyeM()}; }
  // The lowest eye height the walk lowers to and the panel's slider goes to: the floor stays in
  // front of the near plane.
  double lowestEyeM() const { return 2.0 * nearM(); }
  // The highest eye height the walk raises to and the panel's slider goes to: 3 m, or the model's
  // size in a smaller one.
  double highestEyeM() const { return std::min(3.0, sizeM()); }

  double speedMps = 1.4;  // a walking pace; in a model under 2.8 m across, half its size a second
  double eyeHeightM = 1.6;
  double fovYDeg = 60.0;

 private:
  void lookAt(const glm::dvec3& target);  // level, from where it stands
  double sizeM() const;  // the bounds' diagonal
  glm::dvec3 boundsCentre() const { return 0.5 * (frame_.boundsMin + frame_.boundsMax); }
  double nearM() const;  // the near plane's distance, scaled to the model
  double farM(const glm::dvec3& eye) const;
  // Where the start stands in no room (in a wall between a building's rooms, in its courtyard): to
  // the nearest point of free space (freeSpaceAt) on a 0.25 m grid within 4 m, else on a grid of
  // 16 steps over the plan (an L-shaped building's missing corner). In free space, looks the
  // longest way clear to a face. False where it found no free space: the start stays.
  bool stepIntoFreeSpace();
  // Outside the bounds over their least corner, looking down at their centre, all of them in view.
  void lookFromOutside();

  SceneFrame frame_;
  bool outside_ = false;
  bool startGiven_ = false;
  glm::dvec3 up_{0.0};
  glm::dvec3 ground_{0.0};   // the point on the floor plane below the eye
  glm::dvec3 forward_{0.0};  // unit view direction
};

}  // namespace radmesh
