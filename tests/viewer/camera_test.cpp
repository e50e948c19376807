// The walkthrough camera: where it starts in closed and open scenes, and how it walks and turns.
#include "viewer/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/cells/find_cells.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/up_axis.h"
#include "tests/solver/turned_scene.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

SceneFrame room(Vec3 size, int upAxis = 2, int openSide = -1) {
  SceneFrame frame;
  frame.boundsMax = size;
  frame.upAxis = upAxis;
  frame.openSide = openSide;
  return frame;
}

bool inside(const Vec3& p, const SceneFrame& f) {
  return glm::all(glm::greaterThan(p, f.boundsMin)) && glm::all(glm::lessThan(p, f.boundsMax));
}

TEST(WalkCamera, StartsInsideAClosedRoomAtEyeHeightLookingLevelAtTheCentre) {
  const SceneFrame office = room({7.0, 5.0, 2.7});
  const RenderView view = WalkCamera(office).view();
  EXPECT_TRUE(inside(view.eye, office));
  EXPECT_DOUBLE_EQ(view.eye.z, 1.6);
  EXPECT_DOUBLE_EQ(view.look.z, view.eye.z);  // level
  const Vec3 toCentre = Vec3(3.5, 2.5, 1.6) - view.eye;
  EXPECT_NEAR(glm::dot(glm::normalize(view.look - view.eye), glm::normalize(toCentre)), 1.0, 1e-12);
  EXPECT_NO_THROW(validateView(view));
}

// The viewer sends a camera outside every room into the room solved first. On building:2x2 it
// starts in the wall between the spine and the first room, and 0.35 of the spine's cell bounds
// (its voxels', reaching past the corridor's walls) from their centre stood it in the outer wall.
TEST(WalkCamera, ACellsRoomIsEnteredInsideItsWalls) {
  const Scene building = loadScene("building:2x2");
  const CellPartition partition = findCells(building, meshScene(building));
  const Cell& spine = partition.cells.at(0);
  ASSERT_EQ(spine.name, "spine");
  ASSERT_LT(spine.boundsMin.x, -0.2);  // past the outer wall, which is 0.2 m thick at x < 0
  WalkCamera camera(sceneFrame(building));
  camera.standIn(spine.boundsMin, spine.boundsMax, {-1.0, -1.0}, WalkCamera::kCellReach);
  const Vec3 eye = camera.view().eye;
  EXPECT_GT(eye.x, 0.0);  // inside the 2.4 m wide corridor
  EXPECT_LT(eye.x, 2.4);
  EXPECT_GT(eye.y, 0.0);
  EXPECT_LT(eye.y, spine.boundsMax.y);
}

// building:2x2's start, 0.35 of the bounds from their centre, falls in the wall between the spine
// and the first room (x 2.4 to 2.6): the render and a walk without cells showed a wall's inside.
// It steps to the nearest free space, the spine, and looks down it.
TEST(WalkCamera, AStartInsideAWallStepsIntoTheNearestFreeSpace) {
  const SceneFrame frame = sceneFrame(loadScene("building:2x2"));
  const RenderView view = WalkCamera(frame).view();
  EXPECT_TRUE(freeSpaceAt(frame, view.eye, 0.3));
  EXPECT_FALSE(freeSpaceAt(frame, Vec3(2.44, 1.9, 1.6), 0.3));  // where it would have stood
  EXPECT_GT(view.eye.x, 0.0);  // in the 2.4 m wide spine
  EXPECT_LT(view.eye.x, 2.4);
  EXPECT_LT(glm::distance(view.eye, Vec3(2.44, 1.9, 1.6)), 4.0 * std::sqrt(2.0));
  EXPECT_GT(clearDistance(frame, view.eye, glm::normalize(view.look - view.eye)), 5.0);  // down the corridor
  // A start in free space stays where it was: the office's.
  const SceneFrame office = sceneFrame(loadScene("office"));
  const Vec3 eye = WalkCamera(office).view().eye;
  EXPECT_TRUE(freeSpaceAt(office, eye, 0.3));
  EXPECT_NEAR(eye.x, office.boundsMin.x + 0.15 * (office.boundsMax.x - office.boundsMin.x), 1e-9);
}

// building:1x1's start corner is free space, and the start looked from it at the bounds' centre,
// into the spine's wall a metre away; it looks the longest way clear, down the spine, as a start
// stepped out of a wall does.
TEST(WalkCamera, AStartInFreeSpaceLooksTheLongestWayClear) {
  const SceneFrame frame = sceneFrame(loadScene("building:1x1"));
  const RenderView view = WalkCamera(frame).view();
  EXPECT_NEAR(view.eye.x, 1.33, 1e-12);  // where it stood: in the corner, free space
  EXPECT_NEAR(view.eye.y, 1.03, 1e-12);
  EXPECT_EQ(glm::normalize(view.look - view.eye), Vec3(0.0, 1.0, 0.0));  // down the spine
  EXPECT_NEAR(clearDistance(frame, view.eye, Vec3(0.0, 1.0, 0.0)), 6.97, 1e-12);
  Vec3 toCentre = 0.5 * (frame.boundsMin + frame.boundsMax) - view.eye;
  toCentre.z = 0.0;
  EXPECT_LT(clearDistance(frame, view.eye, glm::normalize(toCentre)), 1.5);  // where it looked
}

// A 4 x 4 m room (6 faces) with a 1 m square desk top at 0.75 m whose corner is at (x, y).
std::vector<FrameFace> roomWithDesk(double x, double y) {
  const double s = 4.0, h = 2.7;
  std::vector<FrameFace> faces = {
      {{{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}}},  // floor, facing up
      {{{0, 0, h}, {0, s, h}, {s, s, h}, {s, 0, h}}},  // ceiling, facing down
      {{{0, 0, 0}, {0, s, 0}, {0, s, h}, {0, 0, h}}},  {{{s, 0, 0}, {s, 0, h}, {s, s, h}, {s, s, 0}}},
      {{{0, 0, 0}, {0, 0, h}, {s, 0, h}, {s, 0, 0}}},  {{{0, s, 0}, {s, s, 0}, {s, s, h}, {0, s, h}}},
      {{{x, y, 0.75}, {x + 1, y, 0.75}, {x + 1, y + 1, 0.75}, {x, y + 1, 0.75}}}};
  return faces;
}

// The start view looks at the furniture: a desk in the corner where the camera would stand sends
// it to the opposite corner (office3 faced a bare corner); elsewhere it keeps the least corner.
TEST(WalkCamera, StartsAcrossTheRoomFromFurnitureInItsCorner) {
  const SceneFrame cornered = frameOf(roomWithDesk(0.2, 0.2), 2);
  EXPECT_DOUBLE_EQ(cornered.furnitureAreaM2, 1.0);  // the desk alone: not the floor, nor the ceiling
  EXPECT_EQ(cornered.furnitureCentre, Vec3(0.7, 0.7, 0.75));
  EXPECT_EQ(WalkCamera::cornerFacingFurniture(cornered), glm::dvec2(1.0, 1.0));
  RenderView view = WalkCamera(cornered).view();
  EXPECT_NEAR(view.eye.x, 3.4, 1e-12);  // 0.15 of the room from its greatest corner
  EXPECT_NEAR(view.eye.y, 3.4, 1e-12);
  EXPECT_GT(glm::dot(view.look - view.eye, Vec3(0.7, 0.7, 0) - view.eye), 0.0);  // towards the desk
  for (const auto& [x, y] : {std::pair{1.5, 1.5}, {2.8, 0.2}, {0.2, 2.8}, {2.8, 2.8}}) {
    const SceneFrame frame = frameOf(roomWithDesk(x, y), 2);
    EXPECT_EQ(WalkCamera::cornerFacingFurniture(frame), glm::dvec2(-1.0, -1.0)) << x << ", " << y;
    view = WalkCamera(frame).view();
    EXPECT_NEAR(view.eye.x, 0.6, 1e-12);
  }
  // Against the middle of the least x wall: across to the greatest x.
  EXPECT_EQ(WalkCamera::cornerFacingFurniture(frameOf(roomWithDesk(0.2, 1.5), 2)), glm::dvec2(1.0, -1.0));
}

TEST(WalkCamera, LowersTheEyeInALowRoom) {
  const RenderView view = WalkCamera(room({1.0, 1.0, 0.5})).view();
  EXPECT_DOUBLE_EQ(view.eye.z, 0.3);  // 60% of the height, under 1.6 m
}

// The near plane, the far plane and the walking pace follow the model's size: a room exported in
// millimetres (2.7 mm tall) was drawn black behind a near plane of 5 mm.
TEST(WalkCamera, NearFarAndPaceFollowTheModelsSize) {
  const SceneFrame millimetres = room({0.004, 0.003, 0.0027});
  const double diagonal = glm::length(millimetres.boundsMax);
  WalkCamera small(millimetres);
  RenderView view = small.view();
  EXPECT_DOUBLE_EQ(view.nearM, 0.002 * diagonal);
  EXPECT_DOUBLE_EQ(view.farM, 4.0 * diagonal);
  EXPECT_DOUBLE_EQ(view.eye.z, 0.6 * 0.0027);
  EXPECT_LT(view.nearM, 0.01 * view.eye.z);
  EXPECT_DOUBLE_EQ(small.speedMps, 0.5 * diagonal);
  EXPECT_NO_THROW(validateView(view));
  // The panel's sliders span the model's own scale, and a room's metres in a room.
  EXPECT_DOUBLE_EQ(small.speedRange().low, 0.01 * diagonal);
  EXPECT_DOUBLE_EQ(small.eyeHeightRange().low, 2.0 * view.nearM);
  EXPECT_DOUBLE_EQ(small.eyeHeightRange().high, diagonal);
  EXPECT_LT(small.speedRange().low, small.speedMps);
  small.update(WalkInput{.rise = -1.0}, 100.0);  // lowered, the floor stays beyond the near plane
  EXPECT_DOUBLE_EQ(small.view().eye.z, 2.0 * view.nearM);

  // The same room in kilometres: near and the pace stay a walker's, the far plane reaches past it.
  WalkCamera large(room({4000.0, 3000.0, 2700.0}));
  view = large.view();
  EXPECT_DOUBLE_EQ(view.nearM, 0.05);
  EXPECT_DOUBLE_EQ(view.farM, 4.0 * glm::length(Vec3(4000.0, 3000.0, 2700.0)));
  EXPECT_DOUBLE_EQ(view.eye.z, 1.6);
  EXPECT_DOUBLE_EQ(large.speedMps, 1.4);
  EXPECT_DOUBLE_EQ(large.speedRange().low, 0.05);
  EXPECT_DOUBLE_EQ(large.eyeHeightRange().high, 3.0);
}

// The eye-height slider stops where lowering the eye stops, twice the near plane: its 2 cm had set
// the eye of a 7 m room (near plane 1.8 cm) below the walk's 3.6 cm, where the walk then kept it.
TEST(WalkCamera, TheEyeHeightSliderStopsWhereTheWalkDoes) {
  WalkCamera camera(room({7.0, 5.0, 2.7}));
  const double nearM = camera.view().nearM;
  EXPECT_DOUBLE_EQ(nearM, 0.002 * glm::length(Vec3(7.0, 5.0, 2.7)));
  EXPECT_DOUBLE_EQ(camera.eyeHeightRange().low, 2.0 * nearM);
  camera.update(WalkInput{.rise = -1.0}, 100.0);
  EXPECT_DOUBLE_EQ(camera.eyeHeightM, camera.eyeHeightRange().low);
  // Set at the slider's end, it stays there when lowered.
  camera.eyeHeightM = camera.eyeHeightRange().low;
  camera.update(WalkInput{.rise = -1.0}, 1.0);
  EXPECT_DOUBLE_EQ(camera.eyeHeightM, 2.0 * nearM);
}

TEST(WalkCamera, LooksIntoAnOpenSideFromOutsideSeeingAllOfIt) {
  // A y-up unit box open at z = 0 (side 2 * 2 + 0), like the Cornell box.
  WalkCamera camera(room({1.0, 1.0, 1.0}, 1, 4));
  const RenderView view = camera.view();
  EXPECT_LT(view.eye.z, 0.0);
  EXPECT_DOUBLE_EQ(view.eye.x, 0.5);
  EXPECT_DOUBLE_EQ(view.eye.y, 0.5);
  EXPECT_EQ(view.up, Vec3(0, 1, 0));
  // The opening's edges (0.5 m off its centre) lie within the vertical field of view.
  const double halfAngle = std::atan(0.5 / -view.eye.z);
  EXPECT_LT(halfAngle, glm::radians(0.5 * camera.fovYDeg));
  EXPECT_GT(view.look.z, view.eye.z);
}

// A model with no free space to stand in (examp1.mgf's luminaire, a trough 1.2 x 0.26 x 0.09 m open
// at the top) is looked at from outside, all of it in view; the closed 1 m furnace is still
// entered.
TEST(WalkCamera, AModelWithNoRoomToStandInIsLookedAtFromOutside) {
  const double x = 1.2, y = 0.26, z = 0.09;
  std::vector<FrameFace> trough = {
      {{{0, 0, 0}, {x, 0, 0}, {x, y, 0}, {0, y, 0}}},  // the bottom, facing up
      {{{0, 0, 0}, {0, 0, z}, {x, 0, z}, {x, 0, 0}}},  // four sides facing in
      {{{0, y, 0}, {x, y, 0}, {x, y, z}, {0, y, z}}},
      {{{0, 0, 0}, {0, y, 0}, {0, y, z}, {0, 0, z}}},
      {{{x, 0, 0}, {x, 0, z}, {x, y, z}, {x, y, 0}}}};
  const SceneFrame frame = frameOf(trough, 2);
  WalkCamera camera(frame);
  EXPECT_TRUE(camera.looksInFromOutside());
  const RenderView view = camera.view();
  EXPECT_FALSE(inside(view.eye, frame));
  EXPECT_GT(view.eye.z, z);  // from above, where it is open
  EXPECT_NO_THROW(validateView(view));
  const Vec3 forward = glm::normalize(view.look - view.eye);
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? x : 0.0, (corner & 2) ? y : 0.0, (corner & 4) ? z : 0.0);
    const double angle = std::acos(glm::dot(forward, glm::normalize(p - view.eye)));
    EXPECT_LT(angle, glm::radians(0.5 * camera.fovYDeg)) << "corner " << corner;
  }
  WalkCamera furnace(sceneFrame(loadScene("furnace")));
  EXPECT_FALSE(furnace.looksInFromOutside());
  EXPECT_TRUE(inside(furnace.view().eye, sceneFrame(loadScene("furnace"))));
}

TEST(WalkCamera, WalksAtItsSpeedOnTheFloorPlane) {
  WalkCamera camera(room({10.0, 10.0, 3.0}));
  camera.speedMps = 2.0;
  const RenderView before = camera.view();
  const Vec3 forward = glm::normalize(before.look - before.eye);
  camera.update(WalkInput{.forward = 1.0}, 0.5);
  const RenderView after = camera.view();
  EXPECT_NEAR(glm::length(after.eye - before.eye), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(after.eye - before.eye, forward), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(after.eye.z, before.eye.z);

  camera.update(WalkInput{.right = 1.0}, 0.25);  // half a metre to the right
  const Vec3 right = glm::cross(forward, Vec3(0, 0, 1));
  EXPECT_NEAR(glm::dot(camera.view().eye - after.eye, right), 0.5, 1e-12);
}

TEST(WalkCamera, RisingChangesTheEyeHeightAboveTheFloor) {
  WalkCamera camera(room({10.0, 10.0, 3.0}));
  camera.speedMps = 1.0;
  camera.update(WalkInput{.rise = 1.0}, 0.2);
  EXPECT_NEAR(camera.eyeHeightM, 1.8, 1e-12);
  EXPECT_NEAR(camera.view().eye.z, 1.8, 1e-12);
  camera.update(WalkInput{.rise = -1.0}, 100.0);  // never under the floor
  EXPECT_GT(camera.view().eye.z, 0.0);
  // Nor above the eye-height slider's top (E had raised it without limit).
  camera.update(WalkInput{.rise = 1.0}, 100.0);
  EXPECT_DOUBLE_EQ(camera.eyeHeightM, 3.0);
  EXPECT_DOUBLE_EQ(camera.eyeHeightRange().high, 3.0);
  WalkCamera small(room({1.0, 1.0, 0.5}));  // the model's size, under 3 m
  small.update(WalkInput{.rise = 1.0}, 100.0);
  EXPECT_DOUBLE_EQ(small.eyeHeightM, 1.5);
  EXPECT_DOUBLE_EQ(small.eyeHeightRange().high, 1.5);
}

// --camera and --look (radmesh render's and radmesh-view's) put the start where they say: the eye
// exactly, looking at the point; without --look at the bounds' centre; --look alone turns the
// walkthrough's own start towards the point.
TEST(WalkCamera, StartsFromTheGivenEyeLookingAtTheGivenPoint) {
  const SceneFrame office = room({7.0, 5.0, 2.7});
  const auto direction = [](const RenderView& v) { return glm::normalize(v.look - v.eye); };
  WalkCamera camera(office);
  EXPECT_FALSE(camera.startGiven());
  camera.startFrom({.eye = Vec3(6.0, 4.0, 2.0), .look = Vec3(1.0, 1.0, 0.5)});
  EXPECT_TRUE(camera.startGiven());  // a cells solve leaves it there
  EXPECT_EQ(camera.view().eye, Vec3(6.0, 4.0, 2.0));
  EXPECT_DOUBLE_EQ(camera.eyeHeightM, 2.0);
  EXPECT_NEAR(glm::dot(direction(camera.view()), glm::normalize(Vec3(-5.0, -3.0, -1.5))), 1.0, 1e-15);

  WalkCamera centred(office);
  centred.startFrom({.eye = Vec3(6.0, 4.0, 2.0)});
  EXPECT_NEAR(glm::dot(direction(centred.view()), glm::normalize(Vec3(3.5, 2.5, 1.35) - Vec3(6.0, 4.0, 2.0))), 1.0,
              1e-15);

  WalkCamera turned(office);
  const Vec3 eye = turned.view().eye;
  turned.startFrom({.look = Vec3(6.0, 4.0, 0.0)});
  EXPECT_TRUE(turned.startGiven());
  EXPECT_EQ(turned.view().eye, eye);
  EXPECT_NEAR(glm::dot(direction(turned.view()), glm::normalize(Vec3(6.0, 4.0, 0.0) - eye)), 1.0, 1e-15);

  WalkCamera unmoved(office);
  unmoved.startFrom({});
  EXPECT_FALSE(unmoved.startGiven());
  EXPECT_EQ(unmoved.view().eye, WalkCamera(office).view().eye);
}

// A start under the floor, or steeper than the mouse may turn (a model seen from below, looking
// up), is kept until moved: the first frame's update snapped the eye up onto the floor and the
// pitch down to 85 degrees, away from the view radmesh render draws from the same flags.
TEST(WalkCamera, AGivenStartBeyondTheWalksLimitsIsKeptUntilMoved) {
  WalkCamera camera(room({7.0, 5.0, 2.7}));
  camera.startFrom({.eye = Vec3(3.5, 2.5, -1.0), .look = Vec3(3.5, 2.6, 2.7)});
  const RenderView given = camera.view();
  const double pitch = std::asin(glm::normalize(given.look - given.eye).z);
  ASSERT_GT(pitch, 1.5);
  camera.update(WalkInput{}, 0.02);
  EXPECT_EQ(camera.view().eye, given.eye);
  EXPECT_NEAR(std::asin(glm::normalize(camera.view().look - camera.view().eye).z), pitch, 1e-12);
  // Turned down, it goes the way it was turned; rising raises it.
  camera.update(WalkInput{.pitchRad = -0.5}, 0.0);
  EXPECT_NEAR(std::asin(glm::normalize(camera.view().look - camera.view().eye).z), pitch - 0.5, 1e-12);
  camera.speedMps = 1.0;
  camera.update(WalkInput{.rise = 1.0}, 0.5);
  EXPECT_NEAR(camera.view().eye.z, -0.5, 1e-12);
  // Above the walk's top (over the roof), it is kept there when raised, and lowers from there.
  camera.startFrom({.eye = Vec3(3.5, 2.5, 5.0), .look = Vec3(3.5, 2.6, 0.0)});
  camera.update(WalkInput{.rise = 1.0}, 0.5);
  EXPECT_DOUBLE_EQ(camera.eyeHeightM, 5.0);
  camera.update(WalkInput{.rise = -1.0}, 0.5);
  EXPECT_DOUBLE_EQ(camera.eyeHeightM, 4.5);
}

// A camera far off still sees the whole scene: the far plane lies past the scene's farthest corner.
TEST(WalkCamera, AGivenEyeFarOffSeesTheWholeScene) {
  const SceneFrame box = room({1.0, 1.0, 1.0});
  WalkCamera camera(box);
  camera.startFrom({.eye = Vec3(0.5, -100.0, 0.5)});
  const RenderView view = camera.view();
  EXPECT_GT(view.farM, glm::length(Vec3(1.0, 1.0, 1.0) - view.eye));
  EXPECT_DOUBLE_EQ(view.farM, 1.5 * (100.5 + 0.5 * std::sqrt(3.0)));
  EXPECT_DOUBLE_EQ(WalkCamera(box).view().farM, 4.0 * std::sqrt(3.0));  // inside, as it was
}

// What makes no view is refused naming the flags given, as radmesh render and radmesh-view say it.
TEST(WalkCamera, AStartThatMakesNoViewIsRefusedNamingItsFlags) {
  const SceneFrame office = room({7.0, 5.0, 2.7});
  const auto refusal = [&](const ViewStart& start, bool fovGiven) {
    WalkCamera camera(office);
    try {
      camera.startFrom(start, fovGiven);
    } catch (const OptionError& e) {
      EXPECT_FALSE(camera.startGiven());
      return std::string(e.what());
    }
    return std::string("not refused");
  };
  EXPECT_EQ(refusal({.eye = Vec3(1.0, 1.0, 1.0), .look = Vec3(1.0, 1.0, 1.0)}, false),
            "--camera/--look: the camera position equals the look point; move one of them");
  EXPECT_EQ(refusal({.eye = Vec3(3.5, 2.5, 1.35)}, true),
            "--camera/--fov: the camera position equals the look point; move one of them (without --look, the "
            "scene's centre 3.5,2.5,1.35)");
  const Vec3 eye = WalkCamera(office).view().eye;
  EXPECT_EQ(refusal({.look = eye + Vec3(0.0, 0.0, 1.0)}, false),
            "--look: the camera looks straight along the up axis; tilt the look point");
  EXPECT_EQ(refusal({.eye = Vec3(1e308, 0.0, 0.0)}, false),
            "--camera/--look: too far apart to aim the camera; give points near the scene");
}

TEST(WalkCamera, YawTurnsLeftAndPitchStopsShortOfStraightUp) {
  WalkCamera camera(room({10.0, 10.0, 3.0}));
  const Vec3 before = glm::normalize(camera.view().look - camera.view().eye);
  camera.update(WalkInput{.yawRad = glm::radians(90.0)}, 0.0);
  const Vec3 after = glm::normalize(camera.view().look - camera.view().eye);
  EXPECT_NEAR(glm::dot(before, after), 0.0, 1e-12);
  EXPECT_NEAR(glm::cross(before, after).z, 1.0, 1e-12);  // counter-clockwise seen from above: left

  camera.update(WalkInput{.pitchRad = 10.0}, 0.0);
  const Vec3 up = glm::normalize(camera.view().look - camera.view().eye);
  EXPECT_GT(up.z, 0.99);
  EXPECT_LT(up.z, 1.0);
  EXPECT_NO_THROW(validateView(camera.view()));
}

TEST(WalkCamera, YUpScenesWalkInTheXzPlane) {
  WalkCamera camera(room({10.0, 3.0, 10.0}, 1));
  const double height = camera.view().eye.y;
  EXPECT_DOUBLE_EQ(height, 1.6);
  camera.update(WalkInput{.forward = 1.0, .right = 1.0}, 1.0);
  EXPECT_DOUBLE_EQ(camera.view().eye.y, height);
}

TEST(WalkCamera, TheYUpTestRoomStartsLevelAtEyeHeightWithYUp) {
  const Scene scene = loadScene(test::dataPath("yup_room.gltf").string());
  const RenderView view = WalkCamera(sceneFrame(scene)).view();
  EXPECT_EQ(view.up, Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(view.eye.y, 1.5);  // 60% of its 2.5 m, under 1.6 m, above the floor at y = 0
  EXPECT_DOUBLE_EQ(view.look.y, view.eye.y);  // level
  // From the corner at the least x and the most z (y-up's `along` is -z), 0.15 of the way in.
  EXPECT_DOUBLE_EQ(view.eye.x, 0.6);
  EXPECT_DOUBLE_EQ(view.eye.z, 2.55);
}

// A scene turned onto y-up, as its bake is, starts where the scene starts, turned the same way.
TEST(WalkCamera, TurningAClosedSceneOntoYUpTurnsItsStartView) {
  for (int up : {2, 0}) {
    Scene scene = loadScene("two-rooms");
    for (Polygon& p : scene.polygons)
      for (Vec3& v : p.vertices) v = up == 2 ? v : Vec3(v.z, v.x, v.y);  // z up, or the same turned x up
    scene.upAxis = up;
    const RenderView before = WalkCamera(sceneFrame(scene)).view();
    for (Polygon& p : scene.polygons)
      for (Vec3& v : p.vertices) v = rotateToYUp(v, up);
    scene.upAxis = 1;
    const RenderView after = WalkCamera(sceneFrame(scene)).view();
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(after.eye[c], rotateToYUp(before.eye, up)[c], 1e-12) << "up " << up;
      EXPECT_NEAR(after.look[c], rotateToYUp(before.look, up)[c], 1e-12) << "up " << up;
    }
    EXPECT_EQ(after.up, Vec3(0, 1, 0));
  }
}

// A closed L-shaped room whose plan misses the corner of its bounds where the start stands, by
// more than the 4 m searched round it: a 12 x 12 m plan without its 6 x 8 m corner at the origin.
// A closed room 2.7 m tall on a plan drawn counter-clockwise: floor, ceiling and walls facing in.
std::vector<FrameFace> roomOn(const std::vector<glm::dvec2>& plan) {
  const double h = 2.7;
  std::vector<FrameFace> faces(2);
  for (const glm::dvec2& p : plan) faces[0].vertices.push_back({p.x, p.y, 0.0});  // the floor, facing up
  for (auto p = plan.rbegin(); p != plan.rend(); ++p) faces[1].vertices.push_back({p->x, p->y, h});
  for (size_t i = 0; i < plan.size(); ++i) {  // walls facing in
    const glm::dvec2 a = plan[i], b = plan[(i + 1) % plan.size()];
    faces.push_back({{{a.x, a.y, 0.0}, {a.x, a.y, h}, {b.x, b.y, h}, {b.x, b.y, 0.0}}});
  }
  return faces;
}

std::vector<FrameFace> lShapedRoom() { return roomOn({{6, 0}, {12, 0}, {12, 12}, {0, 12}, {0, 8}, {6, 8}}); }

// It was taken for a model open on its notched sides and looked into from outside.
TEST(WalkCamera, AnLShapedRoomStartsInsideNotAtTheCornerItMisses) {
  const SceneFrame frame = frameOf(lShapedRoom(), 2);
  EXPECT_EQ(frame.openSide, -1);
  const WalkCamera camera(frame);
  EXPECT_FALSE(camera.looksInFromOutside());
  const RenderView view = camera.view();
  EXPECT_TRUE(freeSpaceAt(frame, view.eye, 0.3)) << view.eye.x << " " << view.eye.y;
  EXPECT_NEAR(view.eye.z, 1.6, 1e-12);
}

// A round room's wall faces in from every side, but only a third of its facets face within 26
// degrees of an axis: it was taken for open on a side and looked at from outside.
TEST(WalkCamera, ARoundRoomStartsInside) {
  for (const int sides : {24, 48, 96}) {
    SCOPED_TRACE(sides);
    std::vector<glm::dvec2> plan;
    for (int k = 0; k < sides; ++k) {
      const double a = 2.0 * std::numbers::pi * (k + 0.5) / sides;
      plan.push_back({5.0 + 5.0 * std::cos(a), 5.0 + 5.0 * std::sin(a)});
    }
    const SceneFrame frame = frameOf(roomOn(plan), 2);
    EXPECT_EQ(frame.openSide, -1);
    const WalkCamera camera(frame);
    EXPECT_FALSE(camera.looksInFromOutside());
    const RenderView view = camera.view();
    EXPECT_LT(glm::length(glm::dvec2(view.eye.x, view.eye.y) - glm::dvec2(5.0, 5.0)), 5.0);
    EXPECT_TRUE(freeSpaceAt(frame, view.eye, 0.3)) << view.eye.x << " " << view.eye.y;
  }
}

// A building drawn at an angle to the axes starts as it does drawn along them, turned: the corner of
// its axis-aligned bounds lies outside it, where the start stood looking at its outer walls.
TEST(WalkCamera, ABuildingDrawnAtAnAngleStartsInsideAsItDoesAlongTheAxes) {
  const Scene along = loadScene("two-rooms");  // the corner of its plan at the origin
  const RenderView before = WalkCamera(sceneFrame(along)).view();
  for (const double degrees : {20.0, 30.0, 60.0}) {
    SCOPED_TRACE(degrees);
    Scene turned = along;
    test::turnAboutVertical(turned, degrees);
    const SceneFrame frame = sceneFrame(turned);
    ASSERT_TRUE(frame.planTurn.turned());
    const WalkCamera camera(frame);
    const RenderView after = camera.view();
    // Modulo quarter turns, the plan lies on its axes as two-rooms does, its corner at the origin,
    // when the turn leaves it as drawn (20 and 30 degrees).
    if (std::abs(frame.planTurn.degrees() - degrees) < 1e-9) {
      EXPECT_LT(glm::length(after.eye - test::turnedAboutVertical(before.eye, degrees)), 1e-9);
      EXPECT_LT(glm::length(after.look - test::turnedAboutVertical(before.look, degrees)), 1e-9);
    }
    EXPECT_TRUE(freeSpaceAt(frame, after.eye, 0.3)) << after.eye.x << " " << after.eye.y;
    EXPECT_FALSE(camera.looksInFromOutside());
    EXPECT_NEAR(after.eye.z, 1.6, 1e-9);
  }
}

}  // namespace
}  // namespace radmesh
