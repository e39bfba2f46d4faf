#pragma once
// An RGB picture of a grid field, written as a PNG with libpng. Grid images are stored in the
// component's image order [ny][nx] with row 0 at y = min, so the writer flips them: row 0 becomes the
// BOTTOM row of the picture and y grows upwards, as in the physical plate.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace peristep::host {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

// One colour per grid point, [ny][nx] row-major.
struct RgbImage {
  std::uint64_t ny = 0, nx = 0;
  std::vector<Rgb> pixels;

  Rgb& at(std::uint64_t row, std::uint64_t col) { return pixels[row * nx + col]; }
  const Rgb& at(std::uint64_t row, std::uint64_t col) const { return pixels[row * nx + col]; }
};

// Coarse grids (tens of points across) would make a tiny file; every point is drawn as a k x k
// block with the smallest k that makes the picture at least this wide.
inline constexpr std::uint64_t kMinimumPictureWidth = 800;
std::uint64_t pictureBlockSize(std::uint64_t nx);

// Writes `image` scaled by pictureBlockSize(image.nx). Throws RunError when the file cannot be written.
void writePng(const std::filesystem::path& file, const RgbImage& image);

}  // namespace peristep::host
