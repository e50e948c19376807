#include "solver/radiosity/effects_plan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/geometry/openings.h"
#include "solver/geometry/scene_rays.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/meshing/occluders.h"
#include "tests/solver/turned_scene.h"

namespace radmesh {
namespace {

// An axis-aligned box of size s at origin o; inward-facing when `inward`, else outward.
void addBox(Scene& scene, Vec3 o, double s, bool inward, int material, bool withTop = true) {
  const Vec3 c[8] = {o + Vec3(0, 0, 0), o + Vec3(s, 0, 0), o + Vec3(s, s, 0), o + Vec3(0, s, 0),
                     o + Vec3(0, 0, s), o + Vec3(s, 0, s), o + Vec3(s, s, s), o + Vec3(0, s, s)};
  // Outward counter-clockwise faces.
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (int f = 0; f < 6; ++f) {
    if (!withTop && f == 1) continue;
    Polygon p;
    p.material = material;
    for (int k = 0; k < 4; ++k) p.vertices.push_back(c[faces[f][inward ? 3 - k : k]]);
    scene.polygons.push_back(p);
  }
}

EffectsPlan planEffects(const Scene& scene, EffectsMode mode = EffectsMode::Auto) {
  return radmesh::planEffects(scene, meshScene(scene, 0.5), mode);
}

Scene greyFurnace() {
  Scene s;
  s.source = "test";
  s.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  addBox(s, Vec3(0), 1.0, true, 0);
  return s;
}

TEST(EffectsPlan, ClosedGreyBoxNeedsOnlyAnalyticFormFactorsOneChannelAndNoEscape) {
  const Scene s = greyFurnace();
  EXPECT_TRUE(isConvexEnclosure(s));
  EXPECT_TRUE(isClosed(s));
  const EffectsPlan plan = planEffects(s);
  EXPECT_FALSE(plan.occlusion);
  EXPECT_FALSE(plan.colour);
  EXPECT_TRUE(plan.interreflection);
  EXPECT_FALSE(plan.escape);
  ASSERT_EQ(plan.effects.size(), 5u);
  EXPECT_EQ(plan.effects[0].name, "occlusion");
}

TEST(EffectsPlan, BoxWithoutLidIsConvexButOpen) {
  Scene s;
  s.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  addBox(s, Vec3(0), 1.0, true, 0, /*withTop=*/false);
  EXPECT_TRUE(isConvexEnclosure(s));
  EXPECT_FALSE(isClosed(s));
  EXPECT_TRUE(planEffects(s).escape);
}

TEST(EffectsPlan, BlockInsideRoomOccludes) {
  Scene s = greyFurnace();
  addBox(s, Vec3(0.4), 0.2, false, 0);
  EXPECT_FALSE(isConvexEnclosure(s));
  EXPECT_TRUE(isClosed(s));  // both surfaces are watertight
  EXPECT_TRUE(planEffects(s).occlusion);
}

TEST(EffectsPlan, WallSplitInTwoAlongAnEdgeStillCloses) {
  Scene s = greyFurnace();
  // Replace the floor (face 0, z = 0) by two halves: its edges are covered by two shorter ones.
  s.polygons.erase(s.polygons.begin());
  s.polygons.push_back({{{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}}, 0, "half"});
  s.polygons.push_back({{{0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0}}, 0, "half"});
  EXPECT_TRUE(isClosed(s));
}

// The unit box with each face exported as n x n quads (an exporter's tessellation), the quad at
// `dent` of the floor lowered by `depth` (negative: raised into the room).
Scene tessellatedBox(int n, int dent = -1, double depth = 0.0) {
  Scene s;
  s.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  Scene box;
  addBox(box, Vec3(0), 1.0, true, 0);
  for (const Polygon& face : box.polygons) {
    const Vec3 o = face.vertices[0], u = face.vertices[1] - o, v = face.vertices[3] - o;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        Polygon q{{}, 0, ""};
        for (const auto& [a, b] : {std::pair{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}})
          q.vertices.push_back(o + u * (double(a) / n) + v * (double(b) / n));
        if (&face == &box.polygons[0] && i * n + j == dent)
          for (Vec3& vertex : q.vertices) vertex.z -= depth;
        s.polygons.push_back(q);
      }
  }
  return s;
}

// A column's sides standing on the floor of the unit room, from `bottom` up to `top`, capped by
// neither end; and a partition wall from wall to wall at x = 0.8.
void addColumnAndPartition(Scene& s, double bottom, double top) {
  const Vec3 c[4] = {{0.2, 0.2, 0}, {0.4, 0.2, 0}, {0.4, 0.4, 0}, {0.2, 0.4, 0}};
  for (int k = 0; k < 4; ++k) {
    const Vec3 a = c[k], b = c[(k + 1) % 4];
    s.polygons.push_back({{a + Vec3(0, 0, bottom), b + Vec3(0, 0, bottom), b + Vec3(0, 0, top), a + Vec3(0, 0, top)}, 0,
                          "column"});
  }
  s.polygons.push_back({{{0.8, 0, 0}, {0.8, 1, 0}, {0.8, 1, 1}, {0.8, 0, 1}}, 0, "partition"});
}

// Their edges end on the floor, the ceiling and the walls, inside those faces, which close them:
// no light leaves there. A column hanging short of the floor leaves its foot open, inside the room.
TEST(EffectsPlan, AColumnAndAPartitionStandingOnFacesLeaveTheRoomClosed) {
  Scene standing = greyFurnace();
  addColumnAndPartition(standing, 0.0, 1.0);
  EXPECT_TRUE(isClosed(standing));
  EXPECT_FALSE(planEffects(standing).escape);
  Scene hanging = greyFurnace();
  addColumnAndPartition(hanging, 0.5, 1.0);
  double open = 0.0;
  for (const BoundarySegment& b : boundarySegments(hanging, 1e-9)) open += glm::length(b.b - b.a);
  EXPECT_NEAR(open, 0.8, 1e-12);  // the column's foot
  EXPECT_TRUE(isClosed(hanging));  // but inside the room: the next test
}

// Open edges inside closed surfaces let no light out: a lamp's quad hanging under the ceiling of a
// closed room leaves it closed, where the same quad over the room, or under it with the room's lid
// off, leaves the scene open. Every ray from the quad's edges meets the room in the first case; some
// in 32 directions meet nothing in the others.
TEST(EffectsPlan, ALampsQuadHangingInAClosedRoomLeavesItClosed) {
  const auto withQuadAt = [](Scene s, double z) {
    s.polygons.push_back({{{0.4, 0.4, z}, {0.4, 0.6, z}, {0.6, 0.6, z}, {0.6, 0.4, z}}, 0, "lamp"});
    return s;
  };
  const Scene inside = withQuadAt(greyFurnace(), 0.9);
  EXPECT_EQ(boundarySegments(inside, 1e-9).size(), 4u);
  EXPECT_TRUE(isClosed(inside));
  const EffectsPlan plan = planEffects(inside);
  EXPECT_FALSE(plan.escape);
  EXPECT_NE(plan.effects[4].reason.find("closed around the 4 open edges"), std::string::npos) << plan.effects[4].reason;
  EXPECT_FALSE(isClosed(withQuadAt(greyFurnace(), 1.5)));
  Scene lidless;
  lidless.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  addBox(lidless, Vec3(0), 1.0, true, 0, /*withTop=*/false);
  EXPECT_FALSE(isClosed(withQuadAt(lidless, 0.9)));
  EXPECT_TRUE(planEffects(withQuadAt(lidless, 0.9)).escape);
}

// A watertight block with nothing around it is closed by its edges, but its faces look out into
// empty space: light leaves. Inside a room, the same block's faces look at the room's walls.
TEST(EffectsPlan, ASolidBlockAloneLetsLightOutAndInsideARoomDoesNot) {
  Scene block;
  block.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  addBox(block, Vec3(0.4), 0.2, false, 0);
  EXPECT_TRUE(boundarySegments(block, 1e-9).empty());
  EXPECT_FALSE(isClosed(block));
  const EffectsPlan plan = planEffects(block);
  EXPECT_TRUE(plan.escape);
  EXPECT_NE(plan.effects[4].reason.find("some face looks out"), std::string::npos) << plan.effects[4].reason;
  Scene room = greyFurnace();
  addBox(room, Vec3(0.4), 0.2, false, 0);
  EXPECT_TRUE(isClosed(room));
}

// The rays' buckets give the answer of the exact visibility the solver's shadow tests use (every
// patch the segment to 100 m away might cross, through their hierarchy), on the office from points
// all over it, and around it, in directions all around. A ramp across the whole office is too large
// for the buckets: every ray tests it.
TEST(SceneRays, AnswerAsTheSolversExactVisibilityDoes) {
  Scene office = builtinScene("office");
  office.polygons.push_back({{{0, 0, 0.1}, {7.35, 0, 2.6}, {7.35, 5.7, 2.6}, {0, 5.7, 0.1}}, 0, "ramp"});
  const SceneRays rays(office);
  const std::vector<Patch> patches = meshScene(office, 0.5);
  const Occluders occluders(patches);  // keeps a pointer to them
  int hits = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o(-1.0 + 9.35 * std::fmod(i * 0.618034, 1.0), -1.0 + 7.7 * std::fmod(i * 0.414214, 1.0),
                 -1.0 + 4.7 * std::fmod(i * 0.732051, 1.0));
    const double z = 1.0 - (i + 0.5) / 1000.0, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = i * 2.399963;
    const Vec3 d(r * std::cos(phi), r * std::sin(phi), z);
    const bool blocked = occluders.segmentBlocked(o, o + 100.0 * d, -1, -1);
    EXPECT_EQ(rays.hits(o, d, 0.0), blocked) << i;
    (blocked ? hits : misses) += 1;
  }
  EXPECT_GT(hits, 1000);  // both answers are asked for
  EXPECT_GT(misses, 100);
}

TEST(EffectsPlan, ATurnedModelAtSiteCoordinatesIsAsClosedAsAtTheOrigin) {
  for (const double degrees : {0.0, 17.0, 30.0, 45.0})
    for (const Vec3& site : {Vec3(0.0), Vec3(1e4, 1e5, 0.0), Vec3(512345.678, 5012345.678, 13.3)}) {
      Scene s = builtinScene("two-rooms");
      test::turnAboutVertical(s, degrees);
      for (Polygon& p : s.polygons)
        for (Vec3& v : p.vertices) v += site;
      EXPECT_TRUE(boundarySegments(s, 1e-7 * sceneDiagonal(s)).empty()) << degrees << " degrees at " << site.x;
      EXPECT_TRUE(isClosed(s)) << degrees << " degrees at " << site.x;
    }
}

TEST(EffectsPlan, ABoxExportedAsThousandsOfQuadsIsAConvexEnclosureUnlessAQuadLeavesTheFloor) {
  EXPECT_TRUE(isConvexEnclosure(tessellatedBox(30)));             // 5400 quads on six planes
  EXPECT_FALSE(isConvexEnclosure(tessellatedBox(30, 437, 1e-3)));  // sunk: behind the other floor quads
  EXPECT_FALSE(isConvexEnclosure(tessellatedBox(30, 437, -1e-3)));  // raised: the rest is behind it
  EXPECT_TRUE(isConvexEnclosure(tessellatedBox(30, 437, -1e-13)));  // raised within rounding
}

TEST(EffectsPlan, ColourAndBlackMaterialsAreDetectedAndAllForcesEverything) {
  Scene s = greyFurnace();
  s.materials[0].rho = Rgb(0.0);
  s.materials[0].emittance = Rgb(1.0, 0.5, 0.2);
  EffectsPlan plan = planEffects(s);
  EXPECT_TRUE(plan.colour);
  EXPECT_FALSE(plan.interreflection);
  plan = planEffects(s, EffectsMode::All);
  EXPECT_TRUE(plan.occlusion && plan.colour && plan.interreflection && plan.escape && plan.nearField);
  EXPECT_NE(plan.effects[2].reason.find("forced"), std::string::npos);
  // Forcing escape on leaves what the rays found: the lost-light warnings read it from the plan.
  EXPECT_TRUE(plan.closed);
  addBox(s, Vec3(3), 1.0, false, 0);  // a block outside the room looks out
  EXPECT_FALSE(planEffects(s).closed);
}

}  // namespace
}  // namespace radmesh
