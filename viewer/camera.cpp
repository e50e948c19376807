#include "viewer/camera.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "solver/scene/scene_error.h"
#include "solver/scene/up_axis.h"

namespace radmesh {

namespace {

constexpr double kMaxPitchRad = 1.48;  // about 85 degrees: never quite along the up axis

glm::dvec3 horizontal(const glm::dvec3& v, const glm::dvec3& up) { return v - up * glm::dot(v, up); }

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
  // Rodrigues' rotation formula.
  return v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle) +
         axis * glm::dot(axis, v) * (1.0 - std::cos(angle));
}

}  // namespace

WalkCamera::WalkCamera(const SceneFrame& frame) : frame_(frame) {
  up_[frame.upAxis] = 1.0;
  speedMps = std::min(speedMps, 0.5 * sizeM());  // a model 4 mm across is crossed in seconds, not a frame
  if (frame.planTurn.turned()) {
    // A building drawn at an angle: the corner of its axis-aligned bounds lies outside it. It starts
    // where it would drawn along the axes, turned back.
    const WalkCamera along(alongItsPlan(frame));
    eyeHeightM = along.eyeHeightM;
    outside_ = along.outside_;
    ground_ = frame.planTurn.toWorld(along.ground_);
    forward_ = frame.planTurn.directionToWorld(along.forward_);
    return;
  }
  outside_ = frame.openSide >= 0;
  const glm::dvec3 extent = frame.boundsMax - frame.boundsMin;
  const glm::dvec3 centre = frame.boundsMin + 0.5 * horizontal(extent, up_);  // on the floor
  if (frame.openSide >= 0) {
    // Look in through the open side from outside, half-way up, far enough to see all of it.
    const int axis = frame.openSide / 2;
    glm::dvec3 outward(0.0);
    outward[axis] = frame.openSide % 2 == 0 ? -1.0 : 1.0;
    eyeHeightM = 0.5 * frame.heightM();
    const int across = 3 - axis - frame.upAxis;  // the open side spans this axis and up
    const double halfSpan = 0.5 * std::max(frame.heightM(), extent[across]);
    const double distanceM = 1.05 * halfSpan / std::tan(glm::radians(0.5 * fovYDeg));
    ground_ = centre + outward * (0.5 * extent[axis] + distanceM);
    lookAt(centre);
  } else {
    // A bake, turned from one frame onto another, starts where its scene does.
    eyeHeightM = std::min(1.6, 0.6 * frame.heightM());
    standIn(frame.boundsMin, frame.boundsMax, cornerFacingFurniture(frame));
    if (!stepIntoFreeSpace()) lookFromOutside();
  }
}

void WalkCamera::lookFromOutside() {
  const UpFrame axes = upFrame(frame_.upAxis);
  const glm::dvec3 centre = boundsCentre();
  // From over the least corner, 30 degrees up, far enough that the bounds' sphere fills the view.
  const double elevation = std::numbers::pi / 6.0;
  const glm::dvec3 towardEye = std::cos(elevation) * glm::normalize(-axes.across - axes.along) + std::sin(elevation) * up_;
  const double distanceM = 1.05 * 0.5 * sizeM() / std::sin(glm::radians(0.5 * fovYDeg));
  const glm::dvec3 eye = centre + distanceM * towardEye;
  eyeHeightM = glm::dot(eye, up_) - frame_.floorLevel();
  ground_ = horizontal(eye, up_) + up_ * frame_.floorLevel();
  forward_ = -towardEye;
  outside_ = true;
}

bool WalkCamera::stepIntoFreeSpace() {
  constexpr double kStepM = 0.25, kReachM = 4.0;
  const UpFrame axes = upFrame(frame_.upAxis);
  // 0.3 m from any wall, or a tenth of a model smaller than 3 m across (the 1 m furnace's corner).
  const glm::dvec3 extent = frame_.boundsMax - frame_.boundsMin;
  const double clearM =
      std::min(0.3, 0.1 * std::min(std::abs(glm::dot(extent, axes.across)), std::abs(glm::dot(extent, axes.along))));
  auto eyeAt = [&](const glm::dvec3& ground) {
    return ground + up_ * (frame_.floorLevel() - glm::dot(ground, up_) + eyeHeightM);
  };
  const glm::dvec3 start = ground_;
  bool free = freeSpaceAt(frame_, eyeAt(start), clearM);
  const auto searchRings = [&](double step, double reach) {  // the square rings of a grid round the start
    for (int ring = 1; !free && ring * step <= reach; ++ring)
      for (int i = -ring; i <= ring && !free; ++i)
        for (int j = -ring; j <= ring && !free; ++j) {
          if (std::max(std::abs(i), std::abs(j)) != ring) continue;
          const glm::dvec3 ground = start + step * (double(i) * axes.across + double(j) * axes.along);
          if ((free = freeSpaceAt(frame_, eyeAt(ground), clearM))) ground_ = ground;
        }
  };
  searchRings(kStepM, kReachM);
  // A corner of the bounds far from the building (an L's or a U's missing corner): over the whole
  // plan, in at most 16 rings (as many points as within 4 m).
  const double plan = std::max(std::abs(glm::dot(extent, axes.across)), std::abs(glm::dot(extent, axes.along)));
  searchRings(std::max(kStepM, plan / 16.0), plan);
  if (!free) return false;
  // Looking the longest way clear to a face: towards the centre (standIn's), or every 45 degrees;
  // down a corridor, across a room, not out through a window. Towards the centre a corner of
  // building:1x1 stood a metre from the spine's wall.
  const glm::dvec3 eye = eyeAt(ground_);
  // The nearer of two rays a hair either side: a ray through the very edge of a door (two-rooms')
  // passed it or not depending on which way the scene was turned (its bake is turned y-up).
  auto clearAlong = [&](const glm::dvec3& direction) {
    return std::min(clearDistance(frame_, eye, rotate(direction, up_, 1e-6)),
                    clearDistance(frame_, eye, rotate(direction, up_, -1e-6)));
  };
  double longest = clearAlong(forward_);
  if (!std::isfinite(longest)) longest = -1.0;
  for (int k = 0; k < 8; ++k) {
    const double a = k * 0.25 * std::numbers::pi;
    const glm::dvec3 direction = std::cos(a) * axes.across + std::sin(a) * axes.along;
    const double clear = clearAlong(direction);
    if (std::isfinite(clear) && clear > longest) longest = clear, forward_ = direction;
  }
  return true;
}

glm::dvec2 WalkCamera::cornerFacingFurniture(const SceneFrame& frame) {
  const glm::dvec2 least{-1.0, -1.0};
  if (!(frame.furnitureAreaM2 > 0.0)) return least;
  const UpFrame axes = upFrame(frame.upAxis);
  const glm::dvec3 offset = frame.furnitureCentre - 0.5 * (frame.boundsMin + frame.boundsMax);
  const glm::dvec3 extent = frame.boundsMax - frame.boundsMin;
  // The furniture's place in halves of each extent: -1 at the least edge, 1 at the greatest.
  glm::dvec2 at(0.0);
  const glm::dvec3 plan[2] = {axes.across, axes.along};
  for (int k = 0; k < 2; ++k) {
    const double size = std::abs(glm::dot(extent, plan[k]));
    at[k] = size > 0.0 ? 2.0 * glm::dot(offset, plan[k]) / size : 0.0;
  }
  // The corner farthest from it, if the least corner is much nearer: standing by the furniture,
  // the view looks away from it (office3's desk fills its least corner, 0.7 from it, 2.2 from the
  // other). Else the least corner stays (the office's furniture is 1.3 from it, 1.6 from the
  // farthest), as it always was.
  const glm::dvec2 farthest{at.x < 0.0 ? 1.0 : -1.0, at.y < 0.0 ? 1.0 : -1.0};
  return glm::length(farthest - at) > 1.5 * glm::length(least - at) ? farthest : least;
}

void WalkCamera::standIn(const Vec3& boundsMin, const Vec3& boundsMax, glm::dvec2 corner, double reach) {
  const glm::dvec3 extent = boundsMax - boundsMin;
  const glm::dvec3 centre = boundsMin + 0.5 * horizontal(extent, up_);
  const UpFrame axes = upFrame(frame_.upAxis);
  ground_ = centre;
  const glm::dvec3 plan[2] = {axes.across, axes.along};
  for (int k = 0; k < 2; ++k) ground_ += corner[k] * reach * std::abs(glm::dot(extent, plan[k])) * plan[k];
  lookAt(centre);
}

void WalkCamera::lookAt(const glm::dvec3& target) {
  forward_ = horizontal(target - ground_, up_);
  // A point-sized or degenerate scene: look along any horizontal axis.
  forward_ = glm::length(forward_) > 1e-9 ? glm::normalize(forward_) : glm::dvec3(up_.z, up_.x, up_.y);
}

void WalkCamera::startFrom(const ViewStart& start, bool fovGiven) {
  RenderView view = this->view();
  const glm::dvec3 centre = boundsCentre();
  if (start.eye) view.eye = *start.eye, view.look = centre;
  if (start.look) view.look = *start.look;
  if (!std::isfinite(glm::length(view.look - view.eye)))
    throw OptionError("--camera/--look: too far apart to aim the camera; give points near the scene");
  view.farM = farM(view.eye);
  try {
    validateView(view);
  } catch (const std::invalid_argument& e) {
    // Without --look the camera looks at the scene's centre: say where that is.
    const std::string centreText =
        start.eye && !start.look
            ? fmt::format(" (without --look, the scene's centre {:.4g},{:.4g},{:.4g})", centre.x, centre.y, centre.z)
            : "";
    // Named as given: the view's own flags, or the walkthrough's start where none is.
    std::string given = std::string(start.eye ? "/--camera" : "") + (start.look ? "/--look" : "") +
                        (fovGiven ? "/--fov" : "");
    given = given.empty() ? "the walkthrough's start" : given.substr(1);
    throw OptionError(fmt::format("{}: {}{}", given, e.what(), centreText));
  }
  if (!start.eye && !start.look) return;
  // Stood on the floor plane below the eye, at the eye's height above the floor: view() gives the
  // eye back exactly ((floor - e) + (e - floor) is 0 in floating point).
  ground_ = view.eye;
  eyeHeightM = glm::dot(view.eye, up_) - frame_.floorLevel();
  forward_ = glm::normalize(view.look - view.eye);
  startGiven_ = true;
}

void WalkCamera::update(const WalkInput& input, double dtSeconds) {
  const glm::dvec3 right = glm::cross(forward_, up_);
  forward_ = rotate(forward_, up_, input.yawRad);
  const double pitch = std::asin(std::clamp(glm::dot(forward_, up_), -1.0, 1.0));
  // A start steeper than the mouse may turn (--look) is kept until turned from, not snapped back.
  const double newPitch =
      std::clamp(pitch + input.pitchRad, std::min(-kMaxPitchRad, pitch), std::max(kMaxPitchRad, pitch));
  forward_ = glm::normalize(rotate(forward_, glm::normalize(right), newPitch - pitch));

  const glm::dvec3 walkForward = glm::normalize(horizontal(forward_, up_));
  const glm::dvec3 walkRight = glm::cross(walkForward, up_);
  const double step = speedMps * dtSeconds;
  ground_ += step * (input.forward * walkForward + input.right * walkRight);
  // Between lowestEyeM and highestEyeM, the slider's ends; an eye started beyond them (--camera
  // under the floor, or above the roof) is kept there until moved towards them, not snapped back.
  eyeHeightM = std::clamp(eyeHeightM + step * input.rise, std::min(lowestEyeM(), eyeHeightM),
                          std::max(highestEyeM(), eyeHeightM));
}

RenderView WalkCamera::view() const {
  RenderView view;
  view.eye = ground_ + up_ * (frame_.floorLevel() - glm::dot(ground_, up_) + eyeHeightM);
  view.look = view.eye + forward_;
  view.up = up_;
  view.fovYDeg = fovYDeg;
  view.nearM = nearM();
  view.farM = farM(view.eye);
  return view;
}

// Four times the model's size, or, from an eye outside the walk's reach (--camera far off), beyond
// the scene's farthest corner from it: the whole scene is seen from anywhere.
double WalkCamera::farM(const glm::dvec3& eye) const {
  const glm::dvec3 centre = boundsCentre();
  return std::max(4.0 * sizeM(),
                  1.5 * (glm::length(eye - centre) + 0.5 * glm::length(frame_.boundsMax - frame_.boundsMin)));
}

double WalkCamera::sizeM() const {
  const double diagonalM = glm::length(frame_.boundsMax - frame_.boundsMin);
  return diagonalM > 0.0 ? diagonalM : 2.5;  // a point-sized scene: a small room's
}

// Within a model of any size (a room exported in mm is 3 mm tall, and a near plane of 5 mm showed
// nothing of it), but no deeper than 5 cm in a large one: the eye walks up to walls.
double WalkCamera::nearM() const { return std::min(0.002 * sizeM(), 0.05); }

}  // namespace radmesh
