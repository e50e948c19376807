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

inline double psnrDb(double rmse) { return rmse > 0.0 ? 20.0 * std::log10(255.0 / rmse) : INFINITY; }

struct TileDifference {
  int column = 0, row = 0;  // the tile's place in the grid
  double rmse = 0.0;        // over RGB in the tile, in 8-bit levels
  double psnrDb = 0.0;
};

struct ImageDifference {
  double rmse = 0.0;    // over RGB, in 8-bit levels
  double psnrDb = 0.0;  // 20 log10(255 / rmse); infinite for identical images
  TileDifference worstTile;  // of a grid of tiles: one wrongly lit object hides in the whole image's figure
  Image diff;           // |actual - expected| x 8, for looking at
};

// The tile of a tilesAcross x tilesDown grid whose RMSE is largest (tiles split the pixels as
// evenly as they go).
inline TileDifference worstTile(const Image& actual, const Image& expected, int tilesAcross, int tilesDown) {
  TileDifference worst{0, 0, -1.0, 0.0};
  for (int ty = 0; ty < tilesDown; ++ty)
    for (int tx = 0; tx < tilesAcross; ++tx) {
      const int x0 = tx * actual.width / tilesAcross, x1 = (tx + 1) * actual.width / tilesAcross;
      const int y0 = ty * actual.height / tilesDown, y1 = (ty + 1) * actual.height / tilesDown;
      double sum = 0.0;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
          for (int c = 0; c < 3; ++c) {
            const size_t i = (static_cast<size_t>(y) * actual.width + x) * 4 + c;
            const double delta = double(actual.rgba[i]) - double(expected.rgba[i]);
            sum += delta * delta;
          }
      const double rmse = std::sqrt(sum / std::max(1.0, 3.0 * (x1 - x0) * (y1 - y0)));
      if (rmse > worst.rmse) worst = {tx, ty, rmse, psnrDb(rmse)};
    }
  return worst;
}

inline ImageDifference compareImages(const Image& actual, const Image& expected, int tilesAcross = 8,
                                     int tilesDown = 8) {
  ImageDifference d;
  d.diff = Image{actual.width, actual.height, std::vector<std::uint8_t>(actual.rgba.size(), 255)};
  for (size_t i = 0; i < actual.rgba.size(); ++i)
    if (i % 4 != 3) d.diff.rgba[i] = std::uint8_t(std::min(255, 8 * std::abs(int(actual.rgba[i]) - int(expected.rgba[i]))));
  d.rmse = imageRmse(actual, expected);
  d.psnrDb = psnrDb(d.rmse);
  d.worstTile = worstTile(actual, expected, tilesAcross, tilesDown);
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
