#include "viewer/exposure.h"

#include <algorithm>

#include "solver/io/mgf_color.h"

namespace radmesh {

double autoExposure(const std::vector<Rgb>& vertexB) {
  std::vector<double> lit;
  lit.reserve(vertexB.size());
  for (const Rgb& b : vertexB) lit.push_back(luminance(b));
  if (lit.empty()) return 1.0;
  const auto percentile95 = lit.begin() + static_cast<std::ptrdiff_t>(0.95 * double(lit.size() - 1));
  std::nth_element(lit.begin(), percentile95, lit.end());
  double reference = *percentile95;
  // Early in a solve most vertices are still dark: fall back to the brightest one.
  if (reference <= 0.0) reference = *std::max_element(lit.begin(), lit.end());
  return reference > 0.0 ? 0.9 / reference : 1.0;
}

}  // namespace radmesh
