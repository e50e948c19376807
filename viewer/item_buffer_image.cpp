#include "viewer/item_buffer_image.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace radmesh {

namespace {

// Neighbouring ids get distant hues: the golden angle spreads consecutive ids around the circle.
std::array<std::uint8_t, 3> patchColour(int id) {
  const double hue = std::fmod(id * 0.6180339887498949, 1.0) * 6.0;
  const double value = 0.65 + 0.35 * ((id / 7) % 2);  // a second cue for ids of similar hue
  const double f = hue - std::floor(hue);
  const double rgb[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
  const double* c = rgb[static_cast<int>(hue) % 6];
  return {std::uint8_t(255 * value * (0.2 + 0.8 * c[0])), std::uint8_t(255 * value * (0.2 + 0.8 * c[1])),
          std::uint8_t(255 * value * (0.2 + 0.8 * c[2]))};
}

}  // namespace

Image falseColourImage(const ItemBuffer& buffer) {
  Image image{buffer.width, buffer.height, std::vector<std::uint8_t>(size_t(buffer.width) * buffer.height * 4)};
  for (size_t i = 0; i < buffer.items.size(); ++i) {
    const int id = buffer.items[i];
    const std::array<std::uint8_t, 3> c =
        id == ItemBuffer::kNone ? std::array<std::uint8_t, 3>{24, 24, 28} : patchColour(id);
    image.rgba[4 * i] = c[0];
    image.rgba[4 * i + 1] = c[1];
    image.rgba[4 * i + 2] = c[2];
    image.rgba[4 * i + 3] = 255;
  }
  return image;
}

}  // namespace radmesh
