#include "viewer/exposure.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "solver/io/mgf_color.h"

namespace radmesh {

namespace {

constexpr double kPercentile = 0.95;
constexpr double kShownAs = 0.7;  // the percentile's shown value, white at 1

}  // namespace

double autoExposure(const DisplayMesh& mesh, const std::vector<Rgb>& vertexB) {
  std::vector<std::pair<double, double>> lit;  // luminance and area of each triangle
  lit.reserve(mesh.indices.size() / 3);
  double totalArea = 0.0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const unsigned a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (std::max({a, b, c}) >= vertexB.size()) return 1.0;  // radiosity of another mesh
    const double area = 0.5 * glm::length(glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]));
    lit.emplace_back((luminance(vertexB[a]) + luminance(vertexB[b]) + luminance(vertexB[c])) / 3.0, area);
    totalArea += area;
  }
  if (lit.empty()) return 1.0;
  std::sort(lit.begin(), lit.end());
  double reference = lit.back().first;
  double below = 0.0;
  for (const auto& [value, area] : lit) {
    below += area;
    if (below >= kPercentile * totalArea) {
      reference = value;
      break;
    }
  }
  // Early in a solve most of the area is still dark: fall back to the brightest triangle.
  if (reference <= 0.0) reference = lit.back().first;
  if (!(reference > 0.0)) return 1.0;
  return std::clamp(kShownAs / reference, std::exp2(-kMaxExposureStops), std::exp2(kMaxExposureStops));
}

StopsSpan exposureSliderSpan(double stops, StopsSpan shown) {
  if (shown.low <= stops && stops <= shown.high) return shown;
  const StopsSpan first;
  if (first.low <= stops && stops <= first.high) return first;
  const double half = 0.5 * (first.high - first.low);
  const double centre = std::clamp(std::round(stops), -kMaxExposureStops + half, kMaxExposureStops - half);
  return {centre - half, centre + half};
}

}  // namespace radmesh
