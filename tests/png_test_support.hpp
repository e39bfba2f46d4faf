#pragma once
// PNG files read back with libpng for the host's picture and plot tests.
#include <png.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "png_writer.hpp"

namespace host_test {

namespace fs = std::filesystem;
using peristep::host::Rgb;

// A PNG decoded to 8-bit RGB, picture row 0 at the top as in the file.
struct Picture {
  std::uint32_t width = 0, height = 0;
  bool colour = false, alpha = false;  // as stored in the file, before conversion to RGB
  std::vector<std::uint8_t> rgb;
  Rgb at(std::uint32_t x, std::uint32_t y) const {
    const std::uint8_t* p = rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3;
    return {p[0], p[1], p[2]};
  }
};

inline Picture readPng(const fs::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str())) throw std::runtime_error(file.string() + ": " + image.message);
  Picture p;
  p.width = image.width;
  p.height = image.height;
  p.colour = image.format & PNG_FORMAT_FLAG_COLOR;
  p.alpha = image.format & PNG_FORMAT_FLAG_ALPHA;
  image.format = PNG_FORMAT_RGB;
  p.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, p.rgb.data(), 0, nullptr)) {
    const std::string message = image.message;
    png_image_free(&image);
    throw std::runtime_error(file.string() + ": " + message);
  }
  return p;
}

// Pixels of exactly this colour.
inline std::size_t countColour(const Picture& p, const Rgb& c) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < p.height; ++y)
    for (std::uint32_t x = 0; x < p.width; ++x) n += p.at(x, y) == c;
  return n;
}

// Pixels that are neither white nor grey: drawn in colour.
inline std::size_t countColoured(const Picture& p, std::uint32_t x0, std::uint32_t y0, std::uint32_t x1, std::uint32_t y1) {
  std::size_t n = 0;
  for (std::uint32_t y = y0; y < y1 && y < p.height; ++y)
    for (std::uint32_t x = x0; x < x1 && x < p.width; ++x) {
      const Rgb c = p.at(x, y);
      n += std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 40;
    }
  return n;
}

// Pixels that are not white (text, lines, colours) in a box.
inline std::size_t countInk(const Picture& p, std::uint32_t x0, std::uint32_t y0, std::uint32_t x1, std::uint32_t y1) {
  std::size_t n = 0;
  for (std::uint32_t y = y0; y < y1 && y < p.height; ++y)
    for (std::uint32_t x = x0; x < x1 && x < p.width; ++x) n += p.at(x, y) != Rgb{255, 255, 255};
  return n;
}

}  // namespace host_test
