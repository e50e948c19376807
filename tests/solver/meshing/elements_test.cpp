// Substructuring's elements (solver/meshing/elements.h): exact counts, areas and orientation.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "solver/meshing/elements.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/patch_fixtures.h"

namespace radmesh::test {
namespace {

Patch unitSquare() { return makePatch({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}); }
Patch rightTriangle() { return makePatch({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}); }

void expectCutsOf(const Patch& parent, const Elements& e, int parentIndex, size_t count) {
  double area = 0.0;
  for (int k = e.first[parentIndex]; k < e.first[parentIndex + 1]; ++k) {
    const Patch& element = e.elements[k];
    EXPECT_EQ(e.patchOf[k], parentIndex);
    EXPECT_NEAR(element.areaM2, parent.areaM2 / count, 1e-15);
    // Counter-clockwise around the parent's normal, like the parent.
    const Vec3 turn = glm::cross(element.vertices[1] - element.vertices[0], element.vertices[2] - element.vertices[0]);
    EXPECT_GT(glm::dot(turn, parent.normal), 0.0);
    EXPECT_EQ(element.normal, parent.normal);
    EXPECT_EQ(element.material, parent.material);
    area += element.areaM2;
  }
  EXPECT_EQ(static_cast<size_t>(e.first[parentIndex + 1] - e.first[parentIndex]), count);
  EXPECT_NEAR(area, parent.areaM2, 1e-14);
}

TEST(Elements, CountIsExactForAGivenMinElement) {
  const std::vector<Patch> patches{unitSquare(), rightTriangle()};
  // The square's edges are 1 m: 0.25 m elements cut it 4 ways per edge, exactly (not 5 for
  // rounding); the triangle's longest edge is sqrt 2 = 1.414 m, so 6 ways, 36 triangles.
  const Elements e = subdivideUniform(patches, 0.25);
  ASSERT_EQ(e.elements.size(), 16u + 36u);
  EXPECT_EQ(e.first, (std::vector<int>{0, 16, 52}));
  expectCutsOf(patches[0], e, 0, 16);
  expectCutsOf(patches[1], e, 1, 36);
  EXPECT_EQ(countElements(patches, 0.25), 52.0);
  EXPECT_EQ(subdivideUniform(patches, 0.3).elements.size(), 16u + 25u);  // ceil(1/0.3) = 4, ceil(1.414/0.3) = 5
  EXPECT_EQ(subdivideUniform(patches, 2.0).elements.size(), 2u);        // larger than both: one element each
}

TEST(Elements, MinElementZeroCutsEveryPatchIntoFour) {
  const std::vector<Patch> patches{unitSquare(), rightTriangle()};
  const Elements e = subdivideUniform(patches, 0.0);
  ASSERT_EQ(e.elements.size(), 8u);
  expectCutsOf(patches[0], e, 0, 4);
  expectCutsOf(patches[1], e, 1, 4);
  // The triangle's four-way split: its middle element is the triangle of the edge midpoints.
  EXPECT_NEAR(glm::length(e.elements[5].centroid - patches[1].centroid), 0.0, 1e-15);
}

TEST(Elements, RefusesAMinElementThatIsNegativeNaNOrMakesTooMany) {
  const std::vector<Patch> patches{unitSquare()};
  EXPECT_THROW(subdivideUniform(patches, -0.1), OptionError);
  EXPECT_THROW(subdivideUniform(patches, std::nan("")), OptionError);
  try {
    subdivideUniform(patches, 1e-9);
    FAIL() << "1e-9 m elements of a square metre were not refused";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("larger --min-element"), std::string::npos) << e.what();
  }
  EXPECT_THROW(subdivideUniform(patches, 0.1, {99, ""}), OptionError);  // 100 elements, limit 99
  EXPECT_EQ(subdivideUniform(patches, 0.1, {100, ""}).elements.size(), 100u);
}

// Elements at their measured peak take at most half the machine's memory: 8 GiB holds 4 Mi of them;
// a large or unknown memory keeps the fixed limit.
TEST(Elements, TheLimitFollowsTheMachinesMemory) {
  constexpr std::size_t kGiB = std::size_t{1} << 30;
  EXPECT_EQ(elementLimit(8 * kGiB).count, 4u << 20);
  EXPECT_EQ(elementLimit(64 * kGiB).count, kMaxElements);
  EXPECT_EQ(elementLimit(0).count, kMaxElements);
  EXPECT_EQ(elementLimit(64 * kGiB).why, "");
  EXPECT_LE(elementLimit().count, kMaxElements);
  if (usableMemoryBytes() > 0) {
    EXPECT_LE(elementLimit().count * kPeakBytesPerElement, usableMemoryBytes() / 2);
  }
  // A count over a limit the memory set says so, with the memory it was given, beside the fix;
  // a limit given as a number says nothing of memory.
  auto refusal = [](const ElementLimit& limit) -> std::string {
    try {
      subdivideUniform({unitSquare()}, 0.001, limit);  // a million elements
    } catch (const OptionError& e) {
      return e.what();
    }
    return "not refused";
  };
  EXPECT_NE(refusal(elementLimit(kGiB)).find("limit of 524288 (half of the 1.0 GiB of memory this process may use"),
            std::string::npos);
  const std::string given = refusal({99, ""});
  EXPECT_NE(given.find("more than the limit of 99; use a larger --min-element"), std::string::npos) << given;
}

TEST(Elements, SplitReplacesAnElementInPlaceByFourChildren) {
  const std::vector<Patch> patches = {unitSquare(), rightTriangle()};
  Elements e = patchesAsElements(patches);
  EXPECT_EQ(e.first, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(e.patchOf, (std::vector<int>{0, 1}));
  EXPECT_EQ(e.level, (std::vector<int>{0, 0}));
  EXPECT_EQ(splitElements(e, {0, 1}), (std::vector<int>{0, 1, 1, 1, 1}));
  EXPECT_EQ(e.first, (std::vector<int>{0, 1, 5}));
  EXPECT_EQ(e.level, (std::vector<int>{0, 1, 1, 1, 1}));
  expectCutsOf(patches[1], e, 1, 4);
  // The middle triangle joins the edge midpoints (m12 m20 m01).
  EXPECT_EQ(e.elements[4].vertices[0], Vec3(0.5, 0.5, 0));
  EXPECT_EQ(e.elements[4].vertices[1], Vec3(0, 0.5, 0));
  EXPECT_EQ(e.elements[4].vertices[2], Vec3(0.5, 0, 0));
  // Split again: the square's children by the quadtree, the first of them at v0.
  EXPECT_EQ(splitElements(e, {1, 0, 0, 0, 0}), (std::vector<int>{0, 0, 0, 0, 1, 2, 3, 4}));
  expectCutsOf(patches[0], e, 0, 4);
  EXPECT_EQ(e.elements[0].vertices[2], Vec3(0.5, 0.5, 0));
  EXPECT_EQ(e.elements[2].vertices[2], Vec3(1, 1, 0));
  EXPECT_EQ(e.level, (std::vector<int>{1, 1, 1, 1, 1, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(longestEdge(e.elements[1]), 0.5);
}

// The levels alone give back the elements, split in any order, bitwise; levels that tile no
// patch are refused.
TEST(Elements, SplitToLevelsRemakesTheElementsFromTheirLevels) {
  const std::vector<Patch> patches = {unitSquare(), rightTriangle()};
  Elements e = patchesAsElements(patches);
  splitElements(e, {1, 1});
  splitElements(e, {0, 0, 1, 0, 0, 0, 0, 1});  // the square's third child, the triangle's middle
  splitElements(e, {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  ASSERT_EQ(e.level, (std::vector<int>{1, 1, 2, 3, 3, 3, 3, 2, 2, 1, 1, 1, 1, 2, 2, 2, 2}));
  const Elements again = splitToLevels(patches, e.level);
  EXPECT_EQ(again.first, e.first);
  EXPECT_EQ(again.patchOf, e.patchOf);
  EXPECT_EQ(again.level, e.level);
  ASSERT_EQ(again.elements.size(), e.elements.size());
  EXPECT_EQ(std::memcmp(again.elements.data(), e.elements.data(), sizeof(Patch) * e.elements.size()), 0);
  EXPECT_EQ(splitToLevels(patches, {0, 0}).elements.size(), 2u);
  for (const std::vector<int>& wrong : std::vector<std::vector<int>>{
           {0}, {0, 0, 0}, {1, 1, 1, 0}, {1, 1, 1, 1, 1}, {0, 2, 1, 1, 1}, {-1, 0}, {0, 40}})
    EXPECT_THROW(splitToLevels(patches, wrong), std::invalid_argument) << ::testing::PrintToString(wrong);
}

}  // namespace
}  // namespace radmesh::test
