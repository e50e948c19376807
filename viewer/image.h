#pragma once
// An 8-bit RGBA image, top row first: what the renderer reads back and what PNG files hold.
#include <cstdint>
#include <string>
#include <vector>

namespace radmesh {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, row-major, top row first
};

// Throws std::runtime_error naming the file when it cannot be written or read.
void writePng(const Image& image, const std::string& path);
Image readPng(const std::string& path);

// Root-mean-square difference over the RGB channels, in 8-bit levels (alpha ignored). Throws
// std::invalid_argument when the sizes differ.
double imageRmse(const Image& a, const Image& b);

}  // namespace radmesh
