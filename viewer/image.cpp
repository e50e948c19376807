#include "viewer/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace radmesh {

void writePng(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    throw std::runtime_error(path + ": refusing to write an empty or malformed image");
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw std::runtime_error(path + ": cannot write the PNG (does the folder exist and is it writable?)");
}

Image readPng(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (!pixels) throw std::runtime_error(path + ": cannot read the image (" + stbi_failure_reason() + ")");
  Image image{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  std::memcpy(image.rgba.data(), pixels, image.rgba.size());
  stbi_image_free(pixels);
  return image;
}

double imageRmse(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size())
    throw std::invalid_argument("images of different sizes cannot be compared");
  double sum = 0.0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double delta = double(a.rgba[i]) - double(b.rgba[i]);
    sum += delta * delta;
  }
  return std::sqrt(sum / std::max(1.0, 3.0 * a.width * a.height));
}

}  // namespace radmesh
