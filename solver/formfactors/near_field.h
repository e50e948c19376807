#pragma once
// Near field: a receiver closer to the shooter than the shooter's size sees the shooter as an
// area, not a point, and the point-source form factor from the shooter's centroid fails there
// (two parallel unit squares 1 apart: 0.1998 area to area, the centroid's value 19 % higher;
// perpendicular ones sharing an edge: 0.2000 against 0.1901); so does a receiver a little farther
// off across a narrow gap (inNearField). For those pairs only, the form factor becomes an area-to-area estimate: the analytic
// point-to-polygon form factor averaged over sub-points of the shooter, times the visibility the
// projection measured.
#include <array>
#include <span>
#include <vector>

#include "solver/formfactors/form_factor_row.h"
#include "solver/meshing/patch.h"

namespace radmesh {

inline constexpr int kNearFieldSubdivisions = 8;  // per edge of each of the shooter's triangles

// A receiver is in a shooter's near field if its nearest point (distanceToPatch) is closer to the
// shooter's centroid than the shooter's diameter (`size`), or if it lies in a plane facing the
// shooter across a gap narrower than that and cutting the near field off at it would leave more
// than kGapTailLimit of the shooter's power misplaced. Across a narrow gap the near receivers are not the whole story:
// beyond them each point estimate misses the shooter's extent by a fraction ~ (size / distance)^2,
// all in the same direction (too little), and replacing the near ones by area-to-area values moves
// their total while the rest keeps its error: a 1 m plate 5 cm above another in 0.1 m cells
// received 3.15 % too little, and in 0.0625 m cells no better. Taylor's expansion of the point
// form factor over a square shooter of area A, for a plane parallel to it at height h, puts what
// the receivers beyond distance r miss at (A / 3) h^2 (r^2 - h^2) / r^6 of the shooter's power; a
// receiver is kept while that, weighted by how squarely its plane faces the shooter, exceeds the
// limit. A perpendicular plane's errors change sign across it and cancel: a wall lighting the
// floor it stands on needs no widening. The nearest point, not the centroid: a receiver much larger
// than the shooter, only its edge close (a 0.1 m emitter 5 cm above a 1 m patch, 5 cm inside its
// edge, the centroids 0.45 m apart), receives mostly at that edge, where the point estimate fails.
inline constexpr double kGapTailLimit = 3e-3;
bool inNearField(const Patch& shooter, double size, const Patch& receiver);
// The distance from `point` to the nearest point of `patch`, taken as flat in its plane (convex).
double distanceToPatch(const Vec3& point, const Patch& patch);
// The farthest a receiver's nearest point can be from the shooter's centroid and be in its near field.
double nearFieldReach(const Patch& shooter, double size);

// Per shooter, ascending: the receivers in its near field (inNearField) which face it (each has a
// part in front of the other's plane).
std::vector<std::vector<int>> findNearFieldReceivers(const std::vector<Patch>& patches);
// The same with patches shooting and `receivers` (their elements, solver/meshing/elements.h)
// receiving: per shooter patch, the receivers in its near field.
std::vector<std::vector<int>> findNearFieldReceivers(const std::vector<Patch>& patches,
                                                     const std::vector<Patch>& receivers);

// The same, one shooter at a time, each found when first asked and kept: a solve stopped early
// asks for the few patches that shot (office3 at 10 % unshot: 311 of 13382). Holds both lists by
// reference.
class NearFieldFinder {
 public:
  NearFieldFinder(const std::vector<Patch>& shooters, const std::vector<Patch>& receivers);
  const std::vector<int>& receiversNear(int shooter);
  // After the receivers split (adaptive subdivision; origin and split as splitElements gives and
  // takes): the grids keep their order, renumbered, with the children merged in, where building
  // them anew would sort every receiver again; every shooter's near receivers are found again.
  void receiversSplit(const std::vector<int>& origin, const std::vector<char>& split);
  // Receivers measured against a shooter, summed over the shooters found so far: what finding
  // costs, for tests (the stacks passed over whole are not counted).
  size_t receiversExamined() const { return examined_; }

 private:
  using Cell = std::array<long long, 3>;
  // A receiver's cell, then its normal in steps of 1e-12: parallel receivers of a cell sort together.
  using Key = std::array<long long, 6>;
  // How far a patch departs from its plane (through its centroid) and from its centroid: bounds on
  // where its vertices can lie.
  struct Spread {
    double bulge = 0.0, radius = 0.0;
  };
  static Spread spreadOf(const Patch& patch);
  // At least kStackSize consecutive receivers with one key: a stack of parallel copies (an MGF
  // array), which a shooter parallel to them passes over whole (neverNear), as none of them can face
  // it. Fewer are measured one by one: passing over them would save little more than the bound costs.
  static constexpr int kStackSize = 8;
  struct Stack {
    int end = 0;         // into Grid::sorted, past its last receiver; its first receiver's normal is the stack's
    double tilt = 0.0;   // the most a receiver's normal differs from the first's (length of the difference)
    Spread spread;       // the largest of its receivers'
  };
  static bool neverNear(const Patch& shooter, const Spread& spread, double size, double reach, const Stack& stack,
                        const Vec3& normal);
  // The receivers of radii (Spread::radius) more than `smallest` and at most cellSize, in cells of
  // that size, sorted by key: a cell's column along z is consecutive, and the centroids and radii are
  // copied in the same order so the distance tests walk memory in sequence.
  struct Grid {
    double cellSize = 0.0, smallest = 0.0;
    std::vector<std::pair<Key, int>> sorted;
    std::vector<Vec3> centroids;
    std::vector<double> radii;
    std::vector<int> stackAt;  // per sorted receiver, the stack it begins, or -1
    std::vector<Stack> stacks;
    bool holds(double radius) const { return radius > smallest && radius <= cellSize; }
    Cell cellOf(const Vec3& point) const;
    Key keyOf(const Patch& receiver) const;
  };
  // Grid k of `grids` made if not yet, with those bounds.
  Grid& gridAt(std::vector<Grid>& grids, size_t k, double cellSize, double smallest);
  void indexStacks(Grid& grid) const;  // centroids, radii and stacks from sorted
  // Adds to near_[i] the receivers of `grid` in the shooter's near field.
  void search(const Grid& grid, int i, const Spread& spread, double reach);

  const std::vector<Patch>& shooters_;
  const std::vector<Patch>& receivers_;
  std::vector<double> size_;    // per shooter, its diameter
  std::vector<double> radius_;  // per receiver, its Spread::radius
  double largest_ = 0.0;        // the largest diameter of a shooter or receiver
  // Shooter class k holds shooters no larger than largest_ / 2^k and more than half that. Its
  // receivers are found in small_[k] (radii at most half its largest size: cells of that size) and
  // in large_[0..k]: large_[b] holds radii from largest_ / 2^(b+1) to largest_ / 2^b, in cells of
  // the latter, so a shooter searches the cells within its reach plus their largest radius, and
  // none much smaller than its own size.
  std::vector<Grid> small_, large_;
  std::vector<std::vector<int>> near_;
  std::vector<char> found_;
  size_t examined_ = 0;
};

// The mean over the shooter's area of the point-to-polygon form factor to the receiver's front,
// without occlusion: the shooter's triangles cut into subdivisions^2 triangles each, one point at
// the centroid of each, weighted by its area; a point behind the receiver's plane sends it nothing.
// A receiver no larger than the shooter (to a slack), wholly in front of it, is sampled instead, by
// reciprocity, at sub-triangles no larger (at least 2 cuts). Two patches apart and wholly in front
// of each other across a gap narrower than the points' spacing (the shooter's diameter over
// `subdivisions`) take the exact polygonToPolygonFormFactor instead.
double areaToAreaFormFactor(const Patch& shooter, const Patch& receiver, int subdivisions = kNearFieldSubdivisions);

// A near pair's unoccluded form factors: from the shooter's centroid (pointToPolygonFormFactor) and
// area to area. Geometry alone, so a solve computes them once per shooter and receiver, when the
// shooter first reaches the receiver: a patch shoots about three times, and the area-to-area
// estimate is 128 closed forms.
struct NearFieldPair {
  double point = 0.0;
  double area = 0.0;
  bool computed = false;
};
// Per receiver in nearReceivers (one shooter's, from findNearFieldReceivers), its pair: `pairs`
// made that long, and the pairs computed of the near receivers the row reaches that had none.
// Those the shooter never reaches (hidden, or behind it) cost nothing: on office3, most of them.
void completeNearFieldPairs(const Patch& shooter, const std::vector<Patch>& receivers,
                            const std::vector<int>& nearReceivers, const FormFactorRow& row,
                            std::vector<NearFieldPair>& pairs);

// Replaces row entries of the near receivers by area-to-area estimates scaled by the visible
// fraction the projection measured (row entry over the unoccluded centroid form factor, at most
// 1). What they lose or gain in all goes to or comes from what lies beyond them, in proportion to
// what the projection saw: the far receivers, the backs and the background (escape). No power is
// created, the row sums to at most what the projection surface caught, and a row that saw no
// background keeps its total. pairs: completeNearFieldPairs' for this row.
void correctNearField(FormFactorRow& row, const std::vector<int>& nearReceivers, std::span<const NearFieldPair> pairs);

}  // namespace radmesh
