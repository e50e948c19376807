#pragma once
// Comparing rendered images with references under an error bound, not byte for byte: Mesa
// versions and solver round-off move a few pixels by a level or two.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "viewer/image.h"

namespace radmesh::test {

struct ImageDifference {
  double rmse = 0.0;    // over RGB, in 8-bit levels
  double psnrDb = 0.0;  // 20 log10(255 / rmse); infinite for identical images
  Image diff;           // |actual - expected| x 8, for looking at
};

inline ImageDifference compareImages(const Image& actual, const Image& expected) {
  ImageDifference d;
  d.diff = Image{actual.width, actual.height, std::vector<std::uint8_t>(actual.rgba.size(), 255)};
  for (size_t i = 0; i < actual.rgba.size(); ++i)
    if (i % 4 != 3) d.diff.rgba[i] = std::uint8_t(std::min(255, 8 * std::abs(int(actual.rgba[i]) - int(expected.rgba[i]))));
  d.rmse = imageRmse(actual, expected);
  d.psnrDb = d.rmse > 0.0 ? 20.0 * std::log10(255.0 / d.rmse) : INFINITY;
  return d;
}

// Sum over pixels of linear light (sRGB decoded, channels added): how bright a frame is.
inline double totalLinearLight(const Image& image) {
  double total = 0.0;
  for (size_t i = 0; i < image.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double c = image.rgba[i] / 255.0;
    total += c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  }
  return total;
}

}  // namespace radmesh::test
