#pragma once
// How the single plane's pixels are laid over the PE mesh (the paper's sections 1.5 and 1.7).
// Every mapping is orthogonal (a pixel's PE row depends on its pixel row only, its PE column on
// its pixel column only), so a projected patch's bounding box covers a rectangle of PEs reached
// by spreading down and then right from the PE of its upper-left pixel, wrapping on the torus.
//   hierarchical: blocks of neighbouring pixels per PE (the paper's mapping)
//   cut-and-stack: pixel p on PE p mod side, so neighbouring pixels sit on neighbouring PEs
//   adaptive: monotone blocks sized from a sample of the projected patches so that each PE
//             row and column gets a similar z-buffering load (scan-directed, after Biagioni & Prins)
#include <span>
#include <string>
#include <vector>

#include "solver/scene/solve_options.h"

namespace radmesh {


// One axis of the plane (pixels) over one axis of the mesh (PEs).
class AxisMapping {
 public:
  AxisMapping() = default;  // no pixels
  static AxisMapping blocks(int pixels, int pes);
  static AxisMapping cyclic(int pixels, int pes);
  // Monotone blocks with about equal summed load per PE; every pixel also carries a floor of
  // kAdaptiveLoadFloor times the mean load, so empty stretches cannot pile onto one PE. With no
  // more pixels than PEs, blocks (one pixel per PE).
  static AxisMapping fromLoads(std::span<const double> loadPerPixel, int pes);

  int pixels() const { return static_cast<int>(peOf_.size()); }
  int pes() const { return static_cast<int>(first_.size()) - 1; }
  int peOf(int pixel) const { return peOf_[pixel]; }
  std::span<const int> pixelsOf(int pe) const {
    return {order_.data() + first_[pe], static_cast<std::size_t>(first_[pe + 1] - first_[pe])};
  }
  int maxPixelsPerPe() const;
  // Shift steps from peOf(begin), moving forward with wrap-around, until every pixel of
  // [begin, end) has been visited (0 when one PE holds them all).
  int stepsToCover(int begin, int end) const;

 private:
  AxisMapping(std::vector<int> peOf, int pes, bool cyclic);

  std::vector<int> peOf_;
  std::vector<int> order_;  // pixels grouped by PE, ascending within a PE
  std::vector<int> first_{0};  // order_[first_[pe] .. first_[pe + 1]) are PE pe's pixels
  bool cyclic_ = false;
};

inline constexpr double kAdaptiveLoadFloor = 0.5;

struct PlaneMapping {
  AxisMapping columns;  // pixel column -> PE column
  AxisMapping rows;     // pixel row -> PE row

  // Hierarchical or cut-and-stack; adaptive starts as hierarchical until loads are known.
  static PlaneMapping uniform(MappingKind kind, int resolution, int peRows, int peCols);
  int maxPixelsPerPe() const { return columns.maxPixelsPerPe() * rows.maxPixelsPerPe(); }
};

}  // namespace radmesh
